// SPDX-License-Identifier: MIT
// The four slots of a contact law (PHYSICS.md 2-3): normal, tangential, rolling, cohesion.
// Each slot holds one law, chosen by name from the lists in contact/laws.hpp. A law owns its
// parameter struct (`Params`, checked once by its `configure`) and the values it keeps per
// contact (`history`), and its pure kernel is inlined into the force loop (dispatch.hpp). What
// one slot passes to the next is below: a law reads only its own parameters and these results.
//
// Kernel signatures, by slot (h: the law's own history values, `history.size()` of them):
//   normal      NormalForce kernel(const Params&, const ContactGeometry&, double* h)
//   cohesion    double kernel(const Params&, const ContactGeometry&, const NormalForce&, double* h)
//               (the attractive magnitude >= 0; the NormalForce is zero when not touching)
//   tangential  Vec3 kernel(const Params&, const ContactGeometry&, const NormalForce&,
//                           double cohesion, double* h, double dt)   (force on i)
//   rolling     RollingTorque kernel(const Params&, const ContactGeometry&, const NormalForce&,
//                                    double cohesion, double* h, double dt)
// A normal law also gives its collision time, its elastic energy (from its history too) and a
// damping coefficient for reports; a cohesion law's Params have `reach_over_d`, the largest gap /
// d_ref at which it acts. `NormalForce::stiffness` is what the tangential and rolling laws use as
// k_n: dF_el/d(delta) of an elastic law, the loading stiffness of a hysteretic one.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/inline.hpp"
#include "core/vec3.hpp"
#include "model/contact/contact_geometry.hpp"

namespace silodem {

// What the normal law tells the other slots about one contact.
struct NormalForce {
  double elastic = 0.0;    // elastic normal force (repulsive > 0), e.g. k_n delta_n
  double damping = 0.0;    // dashpot force
  double total = 0.0;      // elastic + damping, after clipping
  double eta = 0.0;        // normal damping coefficient of this contact (N s/m)
  double stiffness = 0.0;  // contact stiffness d(elastic)/d(delta_n) at this overlap (N/m)
  double adhesion = 0.0;  // the pull the normal law itself gives at this overlap (luding: kc delta)
};

// The normal force a friction or rolling limit is a fraction of (tangential linear_history's
// cap, epsd's limit): |F_n| by default (MFIX, MercuryDPM); with `sees_cohesion` the net compression
// F_n - F_coh; with `adds_adhesion` F_n with the normal law's own pull added back, F_n + kc delta
// (Luding 2008's rule for his adhesive law, as WooDEM implements it). Never negative.
SILODEM_HOT double limit_normal_force(bool sees_cohesion, bool adds_adhesion, const NormalForce& fn,
                                      double cohesion) {
  if (sees_cohesion) return std::max(0.0, fn.total - cohesion);
  if (adds_adhesion) return std::max(0.0, fn.total + fn.adhesion);
  return std::fabs(fn.total);
}

struct RollingTorque {
  Vec3 on_i, on_j;
};

}  // namespace silodem
