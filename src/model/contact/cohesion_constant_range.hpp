// SPDX-License-Identifier: MIT
// Moisture cohesion with a finite range (PHYSICS.md 3; VERIFICATION.md 1.7 item 1):
//   F_coh = F_L,cg  for surface gap s < s_c (including overlap), else 0;  s_c = range * d_ref.
// Pull-off work from equilibrium: F s_c + F^2 / (2 k_n) (test T-C5).
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionConstantRange {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "constant-range";
  static constexpr const char* summary = "F_L,cg up to a gap s_c";

  static constexpr std::array<double, 0> history{};
  struct Params {
    double force = 0.0;         // F_L,cg of this pair (after pair rule / wall factor), N
    double range_over_d = 0.0;  // gap s_c / d_ref
    double reach_over_d = 0.0;  // = range_over_d
  };

  SILODEM_HOT static double kernel(const Params& p, const ContactGeometry& g, const NormalForce&,
                                   double*) {
    return -g.overlap < p.range_over_d * g.d_ref ? p.force : 0.0;
  }
  static std::vector<Field> fields(bool wall) {
    auto f = cohesion_common_fields(wall);
    f.insert(f.begin(), Field::number("range",
                                      "gap s_c up to which the force acts, / d_ref "
                                      "(mean diameter of the pair; d at a wall)")
                            .needed()
                            .at_least(0)
                            .at_most(1));
    return f;
  }
  static Params configure(const ParamValues& v, const LawContext& ctx) {
    return {cohesion_pair_force(v, ctx), v.number("range"), v.number("range")};
  }
};

}  // namespace silodem
