// SPDX-License-Identifier: MIT
// The structure of MFIX's van der Waals cohesion with the moisture force F_L,cg as its plateau
// (PHYSICS.md E9; VERIFICATION.md 2.1):
//   F_coh = F_L,cg                 for gap s <= s_in (including overlap)
//         = F_L,cg (s_in / s)^2    for s_in < s < s_out
//         = 0                      beyond s_out;   s_in, s_out given / d_ref.
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionMfixLike {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "mfix-like";
  static constexpr const char* summary = "constant to s_in (incl. overlap), 1/s^2 to s_out";

  static constexpr std::array<double, 0> history{};
  struct Params {
    double force = 0.0;         // F_L,cg of this pair (after pair rule / wall factor), N
    double inner_over_d = 0.0;  // s_in / d_ref
    double outer_over_d = 0.0;  // s_out / d_ref
    double reach_over_d = 0.0;  // = outer_over_d
  };

  SILODEM_HOT static double kernel(const Params& p, const ContactGeometry& g, const NormalForce&,
                                   double*) {
    const double s = -g.overlap;
    const double s_in = p.inner_over_d * g.d_ref;
    if (s <= s_in) return p.force;
    if (s >= p.outer_over_d * g.d_ref) return 0.0;
    const double r = s_in / s;
    return p.force * r * r;
  }
  static std::vector<Field> fields(bool wall) {
    auto f = cohesion_common_fields(wall);
    f.insert(
        f.begin(),
        {Field::number("inner", "inner cutoff gap s_in / d_ref").needed().above(0).at_most(1),
         Field::number("outer", "outer cutoff gap s_out / d_ref").needed().above(0).at_most(1)});
    return f;
  }
  static Params configure(const ParamValues& v, const LawContext& ctx) {
    if (v.number("outer") <= v.number("inner"))
      throw v.error("outer",
                    "must be larger than 'inner' (" + std::to_string(v.number("inner")) + ")");
    return {cohesion_pair_force(v, ctx), v.number("inner"), v.number("outer"), v.number("outer")};
  }
};

}  // namespace silodem
