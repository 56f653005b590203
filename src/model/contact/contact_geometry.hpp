// SPDX-License-Identifier: MIT
// Geometry and kinematics of one particle-particle or particle-wall contact, computed once per
// contact and handed to every law (PHYSICS.md 2). Sign convention: n points from j (or the wall)
// towards i; overlap > 0 while the surfaces overlap, and the surface gap is -overlap.
#pragma once
#include "core/inline.hpp"
#include "core/vec3.hpp"

namespace silodem {

struct ContactGeometry {
  Vec3 n;                       // unit normal, from j / wall to i
  double overlap = 0.0;         // delta_n = R_i + R_j - |x_i - x_j|  (m)
  double arm_i = 0.0;           // distance from i's centre to the contact point (m)
  double arm_j = 0.0;           // same for j (0 for a wall)
  double r_eff = 0.0;           // R_i R_j / (R_i + R_j); R_i against a wall
  double m_eff = 0.0;           // m_i m_j / (m_i + m_j); m_i against a wall (E5)
  double d_i = 0.0, d_j = 0.0;  // diameters (d_j = 0 for a wall)
  double d_ref = 0.0;           // length that scales cohesion ranges: mean diameter; d_i at a wall
  double inertia_i = 0.0, inertia_j = 0.0;          // moments of inertia (0 for a wall)
  double inv_inertia_i = 0.0, inv_inertia_j = 0.0;  // their inverses (0 for a wall)
  double mass_i = 0.0, mass_j = 0.0;                // masses (0 for a wall)
  Vec3 v_rel;                                       // velocity of i's contact point relative to j's
  double overlap_rate = 0.0;                        // d(delta_n)/dt = -v_rel . n
  Vec3 v_t;                                         // tangential part of v_rel
  Vec3 omega_i, omega_j;  // angular velocities (omega_j = wall's, zero for fixed walls)
};

// I_r of the EPSD law (Ai et al. 2011, Eq. 16): I_r^-1 = (I_i + m_i r_i^2)^-1 + (I_j + m_j
// r_j^2)^-1, the wall term absent. Computed by the law that needs it, not for every contact.
inline double rolling_inertia(const ContactGeometry& g) {
  const double ri = 0.5 * g.d_i, a = g.inertia_i + g.mass_i * ri * ri;
  if (g.mass_j <= 0.0) return a;
  const double rj = 0.5 * g.d_j;
  return 1.0 / (1.0 / a + 1.0 / (g.inertia_j + g.mass_j * rj * rj));
}

struct BodyState {
  Vec3 x, v, omega;
  double radius = 0.0, mass = 0.0, inertia = 0.0, inv_inertia = 0.0;
};

namespace detail {
SILODEM_HOT void finish_kinematics(ContactGeometry& g, const Vec3& v_i, const Vec3& v_j) {
  // Contact-point velocities: v + omega x r, with r = -arm_i n for i and +arm_j n for j.
  const Vec3 vc_i = v_i + cross(g.omega_i, -g.arm_i * g.n);
  const Vec3 vc_j = v_j + cross(g.omega_j, g.arm_j * g.n);
  g.v_rel = vc_i - vc_j;
  const double vn = dot(g.v_rel, g.n);
  g.overlap_rate = -vn;
  g.v_t = g.v_rel - vn * g.n;
}
}  // namespace detail

// Particle i against particle j (centres closer than R_i + R_j + some reach; dist > 0). Inline:
// in the force loop a field no law reads is never computed.
SILODEM_HOT ContactGeometry pair_geometry(const BodyState& i, const BodyState& j) {
  ContactGeometry g;
  const Vec3 d = i.x - j.x;
  const double dist = norm(d);
  const double inv_dist = 1.0 / dist;
  g.n = d * inv_dist;
  g.overlap = i.radius + j.radius - dist;
  // Contact point on the radical plane (MFIX DIST_CL / DIST_CI): arm_i^2 - a^2 = R_i^2 ...
  g.arm_i = 0.5 * dist + 0.5 * (i.radius * i.radius - j.radius * j.radius) * inv_dist;
  g.arm_j = dist - g.arm_i;
  g.r_eff = i.radius * j.radius / (i.radius + j.radius);
  g.m_eff = i.mass * j.mass / (i.mass + j.mass);
  g.d_i = 2.0 * i.radius;
  g.d_j = 2.0 * j.radius;
  g.d_ref = i.radius + j.radius;
  g.mass_i = i.mass;
  g.mass_j = j.mass;
  g.inertia_i = i.inertia;
  g.inertia_j = j.inertia;
  g.inv_inertia_i = i.inv_inertia;
  g.inv_inertia_j = j.inv_inertia;
  g.omega_i = i.omega;
  g.omega_j = j.omega;
  detail::finish_kinematics(g, i.v, j.v);
  return g;
}

// Particle i against a wall surface point p with outward normal n (towards the particle side),
// the wall moving with velocity v_wall. `distance` is the centre-to-surface distance along n.
SILODEM_HOT ContactGeometry wall_geometry(const BodyState& i, const Vec3& n, double distance,
                                          const Vec3& v_wall) {
  ContactGeometry g;
  g.n = n;
  g.overlap = i.radius - distance;
  g.arm_i = distance;
  g.arm_j = 0.0;
  g.r_eff = i.radius;
  g.m_eff = i.mass;
  g.d_i = 2.0 * i.radius;
  g.d_ref = g.d_i;
  g.mass_i = i.mass;
  g.inertia_i = i.inertia;
  g.inv_inertia_i = i.inv_inertia;
  g.omega_i = i.omega;
  detail::finish_kinematics(g, i.v, v_wall);
  return g;
}

}  // namespace silodem
