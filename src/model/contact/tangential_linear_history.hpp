// SPDX-License-Identifier: MIT
// Tangential spring with history, dashpot and Coulomb cap (paper Eq. 8; PHYSICS.md 2, E6).
// This file is the reference example of a contact law: checked parameters, a pure kernel, and
// the equation cited where it is implemented.
//   spring  xi <- rotate(xi) + v_t dt            (accumulated tangential displacement)
//   F_t     = -k_t xi - eta_t v_t,  eta_t = (eta_t/eta_n) eta_n   (MFIX default 0.5),
//             k_t = (k_t/k_n) k_n, k_n the normal law's contact stiffness (MFIX default 2/7)
//   |F_t|  <= mu_s F_n, F_n = |elastic + damping normal force| (MFIX); with cap_sees_cohesion the
//             cap uses the net compressive force max(0, F_n - F_coh) instead.
//   on slip F_t = mu_s F_n along the trial force and the spring is reset to the cap, xi = -F_t/k_t
//             (PHYSICS.md E6: "resets the spring to mu |FN| / kt on slip").
#pragma once
#include <algorithm>
#include <array>
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

  // The spring xi, a vector in the tangent plane; -1 when i and j swap (it is i's).
  static constexpr std::array<double, 3> history{-1.0, -1.0, -1.0};

  struct Params {
    double stiffness_ratio = 0.0;    // k_t / k_n, k_n the normal law's contact stiffness
    double damping_fraction = 0.0;   // eta_t / eta_n
    double friction = 0.0;           // mu_s
    bool cap_sees_cohesion = false;  // Coulomb cap on |F_el + F_damp - F_coh|, not |F_el + F_damp|
    bool cap_adds_adhesion = false;  // Coulomb cap on F_n + kc delta (Luding 2008), not |F_n|
  };

  SILODEM_HOT static Vec3 kernel(const Params& p, const ContactGeometry& g, const NormalForce& fn,
                                 double cohesion, double* h, double dt) {
    const double normal =
        limit_normal_force(p.cap_sees_cohesion, p.cap_adds_adhesion, fn, cohesion);
    // k_t = (k_t / k_n) k_n with k_n = d F_el / d delta_n of the normal law at this overlap: the
    // normal spring constant of the linear law; for a Hertz law it grows as sqrt(delta_n).
    const double k_t = p.stiffness_ratio * fn.stiffness;
    Vec3 spring{h[0], h[1], h[2]};
    rotate_into_tangent_plane(spring, g.n);
    spring += g.v_t * dt;
    const double eta_t = p.damping_fraction * fn.eta;
    Vec3 f = -k_t * spring - eta_t * g.v_t;  // Eq. 8, trial force
    const double f2 = norm2(f);
    const double cap = p.friction * normal;  // Eq. 8 (Coulomb)
    if (f2 > cap * cap) {
      f *= cap / std::sqrt(f2);
      spring = f * (-1.0 / k_t);
    }
    h[0] = spring.x, h[1] = spring.y, h[2] = spring.z;
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
        Field::flag("cap_adds_adhesion",
                    "Coulomb cap on max(0, F_n + kc delta), the normal force with the `luding` "
                    "law's adhesive pull added back (Luding 2008), instead of |F_n|",
                    false),
    };
  }

  static Params configure(const ParamValues& v, const LawContext&) {
    Params p;
    p.stiffness_ratio = v.number("stiffness_ratio");
    p.damping_fraction = v.number("damping_ratio");
    p.friction = v.number("friction");
    p.cap_sees_cohesion = v.flag("cap_sees_cohesion");
    p.cap_adds_adhesion = v.flag("cap_adds_adhesion");
    if (p.cap_sees_cohesion && p.cap_adds_adhesion)
      throw v.error("cap_adds_adhesion",
                    "true is allowed only with cap_sees_cohesion = false (each picks the normal "
                    "force of the cap)");
    return p;
  }
};

}  // namespace silodem
