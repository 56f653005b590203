// SPDX-License-Identifier: MIT
// Moisture cohesion acting only while the surfaces overlap (PHYSICS.md 3):
//   F_coh = F_L,cg  for delta_n > 0, else 0.
// The separation work is F^2 / (2 k_n), so this law gets stickier as the stiffness drops
// (VERIFICATION.md 1.7); a colliding pair is captured below v_crit = f(e) F / sqrt(k_n m_eff).
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionOverlapOnly {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "overlap-only";
  static constexpr const char* summary = "F_L,cg while overlapping (Eq. 13-14)";

  static constexpr std::array<double, 0> history{};
  struct Params {
    double force = 0.0;  // F_L,cg of this pair (after pair rule / wall factor), N
    double reach_over_d = 0.0;
  };

  SILODEM_HOT static double kernel(const Params& p, const ContactGeometry& g, const NormalForce&,
                                   double*) {
    return g.overlap > 0.0 ? p.force : 0.0;
  }
  static std::vector<Field> fields(bool wall) { return cohesion_common_fields(wall); }
  static Params configure(const ParamValues& v, const LawContext& ctx) {
    return {cohesion_pair_force(v, ctx), 0.0};
  }
};

}  // namespace silodem
