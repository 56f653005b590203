// SPDX-License-Identifier: MIT
// Tangential spring with history, dashpot and Coulomb cap (paper Eq. 8; PHYSICS.md 2, E6).
// This file is the reference example of a contact law: checked parameters, a pure kernel, and
// the equation cited where it is implemented.
//   spring  xi <- rotate(xi) + v_t dt            (accumulated tangential displacement)
//   F_t     = -k_t xi - eta_t v_t,  eta_t = (eta_t/eta_n) eta_n   (MFIX default 0.5)
//   |F_t|  <= mu_s F_n, F_n = |elastic + damping normal force| (MFIX); with cap_sees_cohesion the
//             cap uses the net compressive force max(0, F_n - F_coh) instead.
//   on slip F_t = mu_s F_n along the trial force and the spring is reset to the cap, xi = -F_t/k_t
//             (PHYSICS.md E6: "resets the spring to mu |FN| / kt on slip").
#pragma once
#include <cmath>

#include "core/inline.hpp"
#include "model/contact/contact_history.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct TangentialLinearHistory {
  static constexpr Slot slot = Slot::Tangential;
  static constexpr const char* name = "linear_history";
  static constexpr const char* summary =
      "spring with history + dashpot, Coulomb cap (Eq. 8; E6 as MFIX)";

  SILODEM_HOT static Vec3 kernel(const TangentialParams& p, const ContactGeometry& g, double eta_n,
                                 double cap_force, Vec3& spring, double dt) {
    rotate_into_tangent_plane(spring, g.n);
    spring += g.v_t * dt;
    const double eta_t = p.damping_fraction * eta_n;
    Vec3 f = -p.stiffness * spring - eta_t * g.v_t;  // Eq. 8, trial force
    const double f2 = norm2(f);
    const double cap = p.friction * cap_force;  // Eq. 8 (Coulomb)
    if (f2 > cap * cap) {
      f *= cap / std::sqrt(f2);
      spring = f * (-1.0 / p.stiffness);
    }
    return f;
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("stiffness_ratio", "k_t / k_n (MFIX default 2/7)")
            .with_default(2.0 / 7.0)
            .above(0)
            .at_most(10),
        Field::number("damping_ratio", "eta_t / eta_n (MFIX default 0.5)")
            .with_default(0.5)
            .at_least(0)
            .at_most(10),
        Field::number("friction", "sliding friction coefficient mu_s")
            .needed()
            .at_least(0)
            .at_most(10),
        Field::flag("cap_sees_cohesion",
                    "Coulomb cap on the net compressive force max(0, elastic + damping - cohesive) "
                    "instead of |elastic + damping| (MFIX: false)",
                    false),
    };
  }

  static void configure(const ParamValues& v, const LawContext&, ContactLaw& law) {
    // k_t needs k_n: the normal slot is configured first (contact_model.cpp).
    law.tp.stiffness = v.number("stiffness_ratio") * law.np.stiffness;
    law.tp.damping_fraction = v.number("damping_ratio");
    law.tp.friction = v.number("friction");
    law.tp.cap_sees_cohesion = v.flag("cap_sees_cohesion");
    law.tangential = &kernel;
  }
};

}  // namespace silodem
