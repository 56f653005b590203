// SPDX-License-Identifier: MIT
// Linear spring-dashpot normal force (paper Eq. 7; PHYSICS.md 2):
//   F_n = (k_n delta_n + eta_n d(delta_n)/dt) n,  eta_n = 2 zeta sqrt(m_eff k_n),
//   zeta = |ln e| / sqrt(pi^2 + ln^2 e)  (Eq. 9/12 with E2 and E5 applied).
// The dashpot may pull near the end of a contact; `clip_attractive` sets the total to zero then
// (LIGGGHTS limitForce). MFIX does not clip, and only without clipping does the measured
// restitution equal e (Schwager & Poeschel 2007).
#pragma once
#include <algorithm>
#include <cmath>

#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct NormalLinearSpringDashpot {
  static constexpr Slot slot = Slot::Normal;
  static constexpr const char* name = "linear_spring_dashpot";
  static constexpr const char* summary =
      "linear spring + dashpot from restitution (Eq. 7, 9-12; E2, E3, E5)";

  SILODEM_HOT static NormalForce kernel(const NormalParams& p, const ContactGeometry& g) {
    NormalForce f;
    f.eta = 2.0 * p.damping_ratio * std::sqrt(g.m_eff * p.stiffness);
    f.elastic = p.stiffness * g.overlap;
    f.damping = f.eta * g.overlap_rate;
    f.total = f.elastic + f.damping;
    if (p.clip_attractive) f.total = std::max(f.total, 0.0);
    return f;
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("stiffness", "normal spring stiffness k_n", "N/m").needed().above(0),
        Field::number("restitution", "coefficient of restitution e of the original particles")
            .needed()
            .above(0)
            .at_most(1),
        Field::flag("clip_attractive",
                    "clip the attractive dashpot force to zero at the end of a contact (MFIX: "
                    "false; with true, e = 0.1 measures 0.252)",
                    false),
    };
  }

  static void configure(const ParamValues& v, const LawContext& ctx, ContactLaw& law) {
    const double e = v.number("restitution");
    const RestitutionCg r = restitution_cg(e, *ctx.cg);
    if (!r.defined && ctx.cg->restitution_policy == RestitutionPolicy::Energy)
      throw v.error("restitution", r.warning);
    if (!r.warning.empty() && ctx.warnings) ctx.warnings->push_back(r.warning);
    law.np.stiffness = v.number("stiffness");
    law.np.restitution = r.value;
    law.np.damping_ratio = damping_ratio(r.value);
    law.np.clip_attractive = v.flag("clip_attractive");
    law.normal = &kernel;
  }
};

}  // namespace silodem
