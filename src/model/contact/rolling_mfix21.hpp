// SPDX-License-Identifier: MIT
// MFiX 21.3's rolling friction (PHYSICS.md 2 and E10): each particle feels a torque
//   T_i = -L k_n delta_n omega_i / |omega_i|
// against its own angular velocity, with the elastic normal force only and no lever arm: MFiX
// 21.3's coefficient MEW_R (MEW_RW at a wall) multiplies k_n delta_n directly, so it is a length L
// in metres (des/calc_force_dem.f and des/calc_collision_wall_mod.f of MFiX 21.3). MFiX 25.x
// multiplies by the diameter instead, which is the `mfix` law; L = mu_r d gives the same torque.
// A rolling sphere decelerates at (5/7) L g / R on a plane.
// `regularize` is rolling_mfix.hpp's, through the same RollingMfix::oppose: w_eps = 10 T dt / I
// scales with the torque, so the viscous stop below w_eps has the coefficient I / (10 dt) per
// contact whatever L is, and stays stable with up to 20 contacts even for L = 0.6 m (the paper's
// mu_r read literally in MFiX 21.3), where T is a hundred times that of `mfix` at mu_r = 0.6.
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/registry.hpp"
#include "model/contact/rolling_mfix.hpp"

namespace silodem {
struct RollingMfix21 {
  static constexpr Slot slot = Slot::Rolling;
  static constexpr const char* name = "mfix-21";
  static constexpr const char* summary =
      "MFiX 21.3: torque L k_n delta_n against each particle's own spin, no diameter (E10)";

  static constexpr std::array<double, 0> history{};
  struct Params {
    double length = 0.0;     // L = MFiX 21.3's MEW_R, a length (m)
    bool regularize = true;  // as RollingMfix's
  };

  SILODEM_HOT static RollingTorque kernel(const Params& p, const ContactGeometry& g,
                                          const NormalForce& fn, double, double*, double dt) {
    // L k_n delta_n, elastic part only, the same on both particles (no d_i, d_j)
    const double magnitude = p.length * fn.elastic;
    RollingTorque t;
    t.on_i =
        RollingMfix::oppose(g.omega_i, magnitude, g.inertia_i, g.inv_inertia_i, p.regularize, dt);
    if (g.d_j > 0.0)
      t.on_j =
          RollingMfix::oppose(g.omega_j, magnitude, g.inertia_j, g.inv_inertia_j, p.regularize, dt);
    return t;
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("length_m",
                      "MFiX 21.3's MEW_R (MEW_RW at a wall) as the length L it is: torque L k_n "
                      "delta_n; L = mu_r d is the `mfix` law",
                      "m")
            .needed()
            .at_least(0)
            .at_most(1),
        Field::flag("regularize",
                    "smooth the sign switch below the spin one step's torque would remove x 10 "
                    "(false: MFiX as is, which chatters at rest)",
                    true)};
  }

  static Params configure(const ParamValues& v, const LawContext&) {
    return {v.number("length_m"), v.flag("regularize")};
  }
};

}  // namespace silodem
