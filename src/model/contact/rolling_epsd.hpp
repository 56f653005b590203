// SPDX-License-Identifier: MIT
// Elastic-plastic spring-dashpot rolling resistance (Ai, Chen, Rotter & Ooi 2011, Powder Technol.
// 206:269, "model type C"; PHYSICS.md 2):
//   k_r = 2.25 k_n mu_r^2 R_eff^2                         (Ai Eq. 13, after Iwashita & Oda)
//   M_k <- rotate(M_k) - k_r omega_r dt,  |M_k| <= mu_r R_eff |F_n|   (Ai Eq. 12, 15)
//   M_d = -eta_r 2 sqrt(I_r k_r) omega_r while |M_k| is below the limit, else 0 (Ai Eq. 17, f = 0)
// with omega_r the tangential part of omega_i - omega_j. The torque acts on i and (opposite) on j.
// Unlike constant-torque laws it holds a sphere at rest without creep or chatter.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/inline.hpp"
#include "model/contact/contact_history.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct RollingEpsd {
  static constexpr Slot slot = Slot::Rolling;
  static constexpr const char* name = "epsd";
  static constexpr const char* summary = "elastic-plastic spring-dashpot (Ai et al. 2011 type C)";

  // The elastic rolling torque M_k on i, a vector in the tangent plane: -1 when i and j swap.
  static constexpr std::array<double, 3> history{-1.0, -1.0, -1.0};
  struct Params {
    double friction = 0.0;             // mu_r
    double stiffness_factor = 2.25;    // k_r = factor k_n mu_r^2 R_eff^2 (Ai et al. 2011)
    double damping_fraction = 0.3;     // eta_r, fraction of critical rolling damping
    bool limit_sees_cohesion = false;  // limit on |F_n - F_coh| instead of |F_n|
    bool limit_adds_adhesion = false;  // limit on F_n + kc delta (Luding 2008) instead of |F_n|
  };

  SILODEM_HOT static RollingTorque kernel(const Params& p, const ContactGeometry& g,
                                          const NormalForce& fn, double cohesion, double* h,
                                          double dt) {
    // k_n: the normal law's contact stiffness at this overlap (the spring constant if linear).
    const double k_r =
        p.stiffness_factor * fn.stiffness * p.friction * p.friction * g.r_eff * g.r_eff;
    Vec3 spring{h[0], h[1], h[2]};
    Vec3 w = g.omega_i - g.omega_j;
    w -= dot(w, g.n) * g.n;
    rotate_into_tangent_plane(spring, g.n);
    spring -= k_r * dt * w;
    const double normal =
        limit_normal_force(p.limit_sees_cohesion, p.limit_adds_adhesion, fn, cohesion);
    const double limit = p.friction * g.r_eff * normal;
    const double m = norm(spring);
    Vec3 torque;
    if (m >= limit) {
      spring *= m > 0.0 ? limit / m : 0.0;
      torque = spring;
    } else {
      // Two bodies that cannot rotate (infinite inertia: both glued to a plate) have no rolling
      // to damp; the product infinity x 0 would be NaN.
      const double i_r = rolling_inertia(g);
      const double c_r = i_r < std::numeric_limits<double>::infinity()
                             ? p.damping_fraction * 2.0 * std::sqrt(i_r * k_r)
                             : 0.0;
      torque = spring - c_r * w;
    }
    h[0] = spring.x, h[1] = spring.y, h[2] = spring.z;
    return {torque, -torque};
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("friction", "rolling friction coefficient mu_r (limit mu_r R_eff |F_n|)")
            .needed()
            .at_least(0)
            .at_most(10),
        Field::number("stiffness_factor", "k_r = factor k_n mu_r^2 R_eff^2 (Ai et al. 2011: 2.25)")
            .with_default(2.25)
            .above(0)
            .at_most(100),
        Field::number("damping_ratio",
                      "rolling viscous damping as a fraction of critical (Ai: 0.3)")
            .with_default(0.3)
            .at_least(0)
            .at_most(2),
        Field::flag("limit_sees_cohesion",
                    "limit torque on the net compressive force max(0, F_n - F_coh) instead of "
                    "|F_n|",
                    false),
        Field::flag("limit_adds_adhesion",
                    "limit torque on max(0, F_n + kc delta), the normal force with the `luding` "
                    "law's adhesive pull added back (Luding 2008), instead of |F_n|",
                    false),
    };
  }

  static Params configure(const ParamValues& v, const LawContext&) {
    const Params p{v.number("friction"), v.number("stiffness_factor"), v.number("damping_ratio"),
                   v.flag("limit_sees_cohesion"), v.flag("limit_adds_adhesion")};
    if (p.limit_sees_cohesion && p.limit_adds_adhesion)
      throw v.error("limit_adds_adhesion",
                    "true is allowed only with limit_sees_cohesion = false (each picks the normal "
                    "force of the limit)");
    return p;
  }
};

}  // namespace silodem
