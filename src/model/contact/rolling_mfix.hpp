// SPDX-License-Identifier: MIT
// MFIX's rolling friction (PHYSICS.md 2 and E10): each particle feels a torque
//   T_i = -mu_r d_i k_n delta_n omega_i / |omega_i|
// against its own angular velocity, with d_i its own diameter ("mew_r is multiplied by the
// diameter") and the elastic normal force only. A constant-torque (Ai et al. 2011 type A) law:
// a rolling sphere decelerates at (10/7) mu_r g on a plane.
// At rest the sign switch makes the torque flip every step: in a bed where cohesion loads every
// contact (k_n delta = F_L,cg) the spin chatters at tens of rad/s and the bed never settles.
// `regularize` (default on) replaces omega/|omega| by omega/max(|omega|, w_eps) with
// w_eps = 10 T dt / I, the spin one contact's torque would remove in ten steps: identical to MFIX
// whenever |omega| > w_eps, and a viscous stop below it that stays stable with up to 20 contacts
// (the summed coefficient stays below 2 I / dt).
// The torque's size is |k_n delta_n|: a normal law with tension (luding, on its adhesive branch)
// gives a negative elastic force, which must not turn the torque into a push along the spin.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct RollingMfix {
  static constexpr Slot slot = Slot::Rolling;
  static constexpr const char* name = "mfix";
  static constexpr const char* summary =
      "MFIX: torque mu_r d k_n delta_n against each particle's own spin (E10)";

  // -magnitude omega / max(|omega|, w_eps), w_eps = 10 magnitude dt / I; below w_eps that is
  // -omega I / (10 dt), which needs neither a square root nor a division (and is 0 at rest).
  SILODEM_HOT static Vec3 oppose(const Vec3& omega, double signed_magnitude, double inertia,
                                 double inv_inertia, bool regularize, double dt) {
    const double magnitude = std::fabs(signed_magnitude);
    const double w2 = norm2(omega);
    const double w_eps = regularize ? 10.0 * magnitude * dt * inv_inertia : 0.0;
    // At rest (w2 = 0) the torque is zero; 0 < w2 <= w_eps^2 needs w_eps > 0, so I is finite.
    const double rest = w2 > 0.0 ? inertia * (-0.1 / dt) : 0.0;
    const double a = w2 > w_eps * w_eps ? -magnitude / std::sqrt(w2) : rest;
    return omega * a;
  }

  static constexpr std::array<double, 0> history{};
  struct Params {
    double friction = 0.0;   // mu_r
    bool regularize = true;  // smooth the sign(omega) switch near omega = 0
  };

  SILODEM_HOT static RollingTorque kernel(const Params& p, const ContactGeometry& g,
                                          const NormalForce& fn, double, double*, double dt) {
    const double elastic = fn.elastic;  // k_n delta_n, elastic part only
    RollingTorque t;
    t.on_i = oppose(g.omega_i, p.friction * g.d_i * elastic, g.inertia_i, g.inv_inertia_i,
                    p.regularize, dt);
    if (g.d_j > 0.0)
      t.on_j = oppose(g.omega_j, p.friction * g.d_j * elastic, g.inertia_j, g.inv_inertia_j,
                      p.regularize, dt);
    return t;
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("friction", "rolling friction coefficient mu_r (torque mu_r d k_n delta_n)")
            .needed()
            .at_least(0)
            .at_most(10),
        Field::flag("regularize",
                    "smooth the sign switch below the spin one step's torque would remove x 10 "
                    "(false: MFIX as is, which chatters at rest)",
                    true)};
  }

  static Params configure(const ParamValues& v, const LawContext&) {
    return {v.number("friction"), v.flag("regularize")};
  }
};

}  // namespace silodem
