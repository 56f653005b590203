// SPDX-License-Identifier: MIT
// The structure of MFIX's van der Waals cohesion with the moisture force F_L,cg as its plateau
// (PHYSICS.md E9; VERIFICATION.md 2.1):
//   F_coh = F_L,cg                 for gap s <= s_in (including overlap)
//         = F_L,cg (s_in / s)^2    for s_in < s < s_out
//         = 0                      beyond s_out;   s_in, s_out given / d_ref.
#pragma once
#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionMfixLike {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "mfix-like";
  static constexpr const char* summary = "constant to s_in (incl. overlap), 1/s^2 to s_out";

  SILODEM_HOT static double kernel(const CohesionParams& p, const ContactGeometry& g) {
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
  static void configure(const ParamValues& v, const LawContext& ctx, ContactLaw& law) {
    if (v.number("outer") <= v.number("inner"))
      throw v.error("outer",
                    "must be larger than 'inner' (" + std::to_string(v.number("inner")) + ")");
    law.cp = CohesionParams{};
    law.cp.force = cohesion_pair_force(v, ctx);
    law.cp.inner_over_d = v.number("inner");
    law.cp.outer_over_d = v.number("outer");
    law.cp.reach_over_d = law.cp.outer_over_d;
    law.cohesion = &kernel;
  }
};

}  // namespace silodem
