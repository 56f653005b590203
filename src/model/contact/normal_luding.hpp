// SPDX-License-Identifier: MIT
// Luding's elasto-plastic adhesive normal force (S. Luding, "Cohesive, frictional powders: contact
// models for tension", Granular Matter 10:235-246, 2008, Eq. 3-6; MercuryDPM ships it as
// LinearPlasticViscoelastic). The adhesion a contact can give grows with the load it has carried:
//   f_hys = k1 delta                 on first loading          (if k2 (delta - delta0) >= k1 delta)
//         = k2 (delta - delta0)      un- and reloading         (if k1 delta > k2 (delta - delta0)
//                                                               > -kc delta)
//         = -kc delta                the adhesive limit        (if -kc delta >= k2 (delta -
//         delta0))
//   delta0 = (1 - k1 / k2) delta_max,  delta_max the largest overlap the contact has reached
//   k2(delta_max) = k1 + (k2_max - k1) min(1, delta_max / delta*),
//   delta* = k2_max / (k2_max - k1) phi_f 2 a_i a_j / (a_i + a_j)   (phi_f = 0: k2 = k2_max always)
//   F_n = f_hys + eta_n d(delta)/dt,  eta_n = 2 zeta(e) sqrt(m_eff k1)
// On the adhesive limit delta_max follows the overlap, delta_max = (k2 + kc) / (k2 - k1) delta, so
// that reloading starts from where the contact is (Luding 2008, below Eq. 6). The largest pull, at
// delta_min = (k2 - k1) / (k2 + kc) delta_max, is
//   f_pull = kc (k2 - k1) / (k2 + kc) delta_max = kc (k2 - k1) / ((k2 + kc) k1) F_max
// for a contact that was pressed with F_max on the loading branch: the pull-off force is a fixed
// fraction of the largest load, so under a consolidation stress sigma the strength of a contact,
// f_pull / d^2, is that fraction of sigma whatever the size d (see the CG rule in
// docs/models/normal_luding.md). The history is delta_max (1 value, kept when i and j swap).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/inline.hpp"
#include "model/contact/normal_common.hpp"

namespace silodem {
struct NormalLuding {
  static constexpr Slot slot = Slot::Normal;
  static constexpr const char* name = "luding";
  static constexpr const char* summary =
      "elasto-plastic adhesive spring, pull-off grows with the largest load (Luding 2008)";
  static constexpr std::array<double, 1> history{1.0};  // delta_max, a scalar

  struct Params {
    double k1 = 0.0;             // loading stiffness, N/m
    double k2_max = 0.0;         // largest un/reloading stiffness, N/m
    double kc = 0.0;             // adhesive stiffness, N/m
    double phi_f = 0.0;          // plastic depth / reduced radius at which k2 reaches k2_max
    double restitution = 1.0;    // e of the viscous part (after the CG policy)
    double damping_ratio = 0.0;  // zeta(e); eta_n = 2 zeta sqrt(m_eff k1)
  };

  // k2 of a contact that has reached delta_max (Luding 2008, Eq. 5), with a_i, a_j the radii.
  SILODEM_HOT static double k2_of(const Params& p, const ContactGeometry& g, double delta_max) {
    const double reduced = g.d_j > 0.0
                               ? 2.0 * (0.5 * g.d_i) * (0.5 * g.d_j) / (0.5 * (g.d_i + g.d_j))
                               : g.d_i;  // 2 a_i a_j / (a_i + a_j); 2 a_i against a wall
    const double star = p.k2_max / (p.k2_max - p.k1) * p.phi_f * reduced;
    const double frac = star > 0.0 ? std::min(1.0, delta_max / star) : 1.0;
    return p.k1 + (p.k2_max - p.k1) * frac;
  }

  SILODEM_HOT static NormalForce kernel(const Params& p, const ContactGeometry& g, double* h) {
    const double delta = g.overlap, delta_max = h[0];
    double f;
    if (delta >= delta_max) {
      // First loading (k2 (delta - delta0) >= k1 delta exactly when delta >= delta_max).
      f = p.k1 * delta;
      h[0] = delta;
    } else {
      const double k2 = k2_of(p, g, delta_max);
      f = k2 * (delta - (1.0 - p.k1 / k2) * delta_max);
      if (f <= -p.kc * delta) {  // the adhesive limit: delta_max follows the overlap
        f = -p.kc * delta;
        h[0] = (k2 + p.kc) / (k2 - p.k1) * delta;
      }
    }
    NormalForce out;
    out.elastic = f;
    out.eta = 2.0 * p.damping_ratio * std::sqrt(g.m_eff * p.k1);
    out.damping = out.eta * g.overlap_rate;
    out.total = out.elastic + out.damping;
    out.stiffness = p.k1;         // what the tangential and rolling laws scale with
    out.adhesion = p.kc * delta;  // f_hys >= -kc delta: f_hys + adhesion >= 0 (Luding's caps)
    return out;
  }

  // The stiffest branch sets the collision time (Eq. 10 with E3 and k2_max).
  static double collision_time(const Params& p, double m_eff, double) {
    return std::numbers::pi /
           std::sqrt(p.k2_max / m_eff * (1.0 - p.damping_ratio * p.damping_ratio));
  }
  // What the contact would give back: the un/reloading spring's 1/2 k2 (delta - delta0)^2 (the
  // rest of the work of loading went into plastic deformation).
  static double elastic_energy(const Params& p, const ContactGeometry& g, const double* h) {
    const double delta_max = std::max(h[0], g.overlap);
    const double k2 = k2_of(p, g, delta_max);
    const double s = g.overlap - (1.0 - p.k1 / k2) * delta_max;
    return 0.5 * k2 * s * s;
  }
  static double damping_coefficient(const Params& p, double m_eff, double) {
    return 2.0 * p.damping_ratio * std::sqrt(m_eff * p.k1);
  }

  static std::vector<Field> fields(bool) {
    return {
        Field::number("stiffness", "loading stiffness k1", "N/m").needed().above(0),
        Field::number("unloading_stiffness", "largest un- and reloading stiffness k2 (>= k1)",
                      "N/m")
            .needed()
            .above(0),
        Field::number("adhesion_stiffness", "adhesive stiffness kc (0: no adhesion)", "N/m")
            .needed()
            .at_least(0),
        Field::number("plastic_depth",
                      "phi_f: the overlap / reduced radius at which k2 reaches its largest value "
                      "(0: k2 = unloading_stiffness at once)")
            .with_default(0.0)
            .at_least(0)
            .at_most(1),
        restitution_field(),
    };
  }

  static Params configure(const ParamValues& v, const LawContext& ctx) {
    Params p;
    p.k1 = v.number("stiffness");
    p.k2_max = v.number("unloading_stiffness");
    if (p.k2_max <= p.k1)
      throw v.error("unloading_stiffness",
                    "must be larger than 'stiffness' (" + std::to_string(p.k1) + " N/m)");
    p.kc = v.number("adhesion_stiffness");
    p.phi_f = v.number("plastic_depth");
    p.restitution = normal_restitution(v, ctx);
    p.damping_ratio = damping_ratio(p.restitution);
    return p;
  }
};

}  // namespace silodem
