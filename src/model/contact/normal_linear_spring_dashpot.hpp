// SPDX-License-Identifier: MIT
// Linear spring-dashpot normal force (paper Eq. 7; PHYSICS.md 2):
//   F_n = (k_n delta_n + eta_n d(delta_n)/dt) n,  eta_n = 2 zeta sqrt(m_eff k_n),
//   zeta = |ln e| / sqrt(pi^2 + ln^2 e)  (Eq. 9/12 with E2 and E5 applied).
// The dashpot may pull near the end of a contact; `clip_attractive` sets the total to zero then
// (LIGGGHTS limitForce). MFIX does not clip, and only without clipping does the measured
// restitution equal e (Schwager & Poeschel 2007).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/inline.hpp"
#include "model/contact/normal_common.hpp"

namespace silodem {
struct NormalLinearSpringDashpot {
  static constexpr Slot slot = Slot::Normal;
  static constexpr const char* name = "linear_spring_dashpot";
  static constexpr const char* summary =
      "linear spring + dashpot from restitution (Eq. 7, 9-12; E2, E3, E5)";
  static constexpr std::array<double, 0> history{};

  struct Params {
    double stiffness = 0.0;        // k_n, N/m
    double restitution = 1.0;      // e actually used (after the CG policy)
    double damping_ratio = 0.0;    // zeta(e); eta_n = 2 zeta sqrt(m_eff k_n)
    bool clip_attractive = false;  // clip the attractive dashpot force at the end of a contact
  };

  SILODEM_HOT static NormalForce kernel(const Params& p, const ContactGeometry& g, double*) {
    NormalForce f;
    f.eta = 2.0 * p.damping_ratio * std::sqrt(g.m_eff * p.stiffness);
    f.elastic = p.stiffness * g.overlap;
    f.damping = f.eta * g.overlap_rate;
    f.total = f.elastic + f.damping;
    if (p.clip_attractive) f.total = std::max(f.total, 0.0);
    f.stiffness = p.stiffness;
    return f;
  }

  // Eq. 10 with E3: t_col = pi / sqrt(k/m - eta^2 / (4 m^2)), eta = 2 zeta sqrt(m k)
  // => t_col = pi / sqrt((k/m)(1 - zeta^2)); independent of the radius and the impact speed.
  static double collision_time(const Params& p, double m_eff, double) {
    return std::numbers::pi /
           std::sqrt(p.stiffness / m_eff * (1.0 - p.damping_ratio * p.damping_ratio));
  }
  static double elastic_energy(const Params& p, const ContactGeometry& g, const double*) {
    return 0.5 * p.stiffness * g.overlap * g.overlap;
  }
  static double damping_coefficient(const Params& p, double m_eff, double) {
    return 2.0 * p.damping_ratio * std::sqrt(m_eff * p.stiffness);
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("stiffness", "normal spring stiffness k_n", "N/m").needed().above(0),
        restitution_field(),
        Field::flag("clip_attractive",
                    "clip the attractive dashpot force to zero at the end of a contact (MFIX: "
                    "false; with true, e = 0.1 measures 0.252)",
                    false),
    };
  }

  static Params configure(const ParamValues& v, const LawContext& ctx) {
    Params p;
    p.stiffness = v.number("stiffness");
    p.restitution = normal_restitution(v, ctx);
    p.damping_ratio = damping_ratio(p.restitution);
    p.clip_attractive = v.flag("clip_attractive");
    return p;
  }
};

}  // namespace silodem
