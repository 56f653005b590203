// SPDX-License-Identifier: MIT
// Hertz normal force with the damping of Tsuji, Tanaka & Ishida (1992, Powder Technol. 71:239),
// calibrated on the restitution in closed form by Antypov & Elliott (2011, EPL 94:50004):
//   F_n = k_H delta^(3/2) + alpha sqrt(m_eff k_H) delta^(1/4) d(delta)/dt,
//   k_H = (4/3) E* sqrt(R_eff),  alpha = sqrt(5) |ln e| / sqrt(pi^2 + ln^2 e).
// With this alpha the restitution is exactly e at every impact speed (the phase-space map
// u = delta^(5/4) turns the equation into the linear spring-dashpot's with damping ratio
// alpha / sqrt(5): Antypov & Elliott 2011; Feng 2026, arXiv:2603.27764). The contact stiffness
// passed on to the other slots is dF_el/d(delta) = (3/2) k_H sqrt(delta).
//   E* = E / (2 (1 - nu^2)) between two particles of the same coal; E / (1 - nu^2) against a wall,
//   which is rigid. E and nu are those of the CG particles as given (no scaling with k).
// The collision of two elastic spheres at speed v lasts t_c = 2 I delta_max / v,
// I = int_0^1 (1 - x^(5/2))^(-1/2) dx = sqrt(pi) Gamma(7/5) / Gamma(9/10) = 1.4716,
// delta_max = (15 m_eff v^2 / (16 E* sqrt(R_eff)))^(2/5) (Johnson 1985, Contact Mechanics, 11.4);
// the time step is set from t_c at `reference_speed` (faster impacts are shorter, as v^(-1/5)).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/inline.hpp"
#include "model/contact/normal_common.hpp"

namespace silodem {
struct NormalHertz {
  static constexpr Slot slot = Slot::Normal;
  static constexpr const char* name = "hertz";
  static constexpr const char* summary =
      "Hertz spring + Tsuji dashpot, restitution exact (Antypov & Elliott 2011)";
  static constexpr std::array<double, 0> history{};

  struct Params {
    double modulus = 0.0;          // E*, Pa
    double restitution = 1.0;      // e actually used (after the CG policy)
    double alpha = 0.0;            // sqrt(5) zeta(e)
    double reference_speed = 1.0;  // m/s, for the collision time
    bool clip_attractive = false;
  };

  SILODEM_HOT static NormalForce kernel(const Params& p, const ContactGeometry& g, double*) {
    NormalForce f;
    const double root = std::sqrt(std::max(g.overlap, 0.0));  // delta^(1/2)
    const double k_h = (4.0 / 3.0) * p.modulus * std::sqrt(g.r_eff);
    f.elastic = k_h * g.overlap * root;                 // k_H delta^(3/2)
    f.eta = p.alpha * std::sqrt(g.m_eff * k_h * root);  // alpha sqrt(m k_H) delta^(1/4)
    f.damping = f.eta * g.overlap_rate;
    f.total = f.elastic + f.damping;
    if (p.clip_attractive) f.total = std::max(f.total, 0.0);
    f.stiffness = 1.5 * k_h * root;
    return f;
  }

  static double peak_overlap(const Params& p, double m_eff, double r_eff) {
    const double v = p.reference_speed;
    return std::pow(15.0 * m_eff * v * v / (16.0 * p.modulus * std::sqrt(r_eff)), 0.4);
  }
  static double collision_time(const Params& p, double m_eff, double r_eff) {
    const double integral = std::sqrt(std::numbers::pi) * std::tgamma(1.4) / std::tgamma(0.9);
    return 2.0 * integral * peak_overlap(p, m_eff, r_eff) / p.reference_speed;
  }
  static double elastic_energy(const Params& p, const ContactGeometry& g, const double*) {
    const double k_h = (4.0 / 3.0) * p.modulus * std::sqrt(g.r_eff);
    return 0.4 * k_h * std::pow(std::max(g.overlap, 0.0), 2.5);
  }
  // For reports: the damping coefficient at the peak overlap of an impact at reference_speed.
  static double damping_coefficient(const Params& p, double m_eff, double r_eff) {
    const double k_h = (4.0 / 3.0) * p.modulus * std::sqrt(r_eff);
    return p.alpha * std::sqrt(m_eff * k_h) * std::pow(peak_overlap(p, m_eff, r_eff), 0.25);
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("youngs_modulus", "Young's modulus E of the CG particles", "Pa")
            .needed()
            .above(0)
            .at_most(1e12),
        Field::number("poisson_ratio", "Poisson's ratio nu")
            .with_default(0.3)
            .at_least(0)
            .below(0.5),
        restitution_field(),
        Field::number("reference_speed",
                      "impact speed whose collision time sets the time step (t_c ~ v^-1/5)", "m/s")
            .with_default(1.0)
            .above(0)
            .at_most(100),
        Field::flag("clip_attractive",
                    "clip the attractive dashpot force to zero at the end of a contact", false),
    };
  }

  static Params configure(const ParamValues& v, const LawContext& ctx) {
    Params p;
    const double nu = v.number("poisson_ratio");
    p.modulus = v.number("youngs_modulus") / ((ctx.wall ? 1.0 : 2.0) * (1.0 - nu * nu));
    p.restitution = normal_restitution(v, ctx);
    p.alpha = std::sqrt(5.0) * damping_ratio(p.restitution);
    p.reference_speed = v.number("reference_speed");
    p.clip_attractive = v.flag("clip_attractive");
    return p;
  }
};

}  // namespace silodem
