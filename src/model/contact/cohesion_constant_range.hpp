// SPDX-License-Identifier: MIT
// Moisture cohesion with a finite range (PHYSICS.md 3; VERIFICATION.md 1.7 item 1):
//   F_coh = F_L,cg  for surface gap s < s_c (including overlap), else 0;  s_c = range * d_ref.
// Pull-off work from equilibrium: F s_c + F^2 / (2 k_n) (test T-C5).
#pragma once
#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionConstantRange {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "constant-range";
  static constexpr const char* summary = "F_L,cg up to a gap s_c";

  SILODEM_HOT static double kernel(const CohesionParams& p, const ContactGeometry& g) {
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
  static void configure(const ParamValues& v, const LawContext& ctx, ContactLaw& law) {
    law.cp = CohesionParams{};
    law.cp.force = cohesion_pair_force(v, ctx);
    law.cp.range_over_d = v.number("range");
    law.cp.reach_over_d = law.cp.range_over_d;
    law.cohesion = &kernel;
  }
};

}  // namespace silodem
