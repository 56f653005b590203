// SPDX-License-Identifier: MIT
// Geometry and kinematics of one particle-particle or particle-wall contact, computed once per
// contact and handed to every law (PHYSICS.md 2). Sign convention: n points from j (or the wall)
// towards i; overlap > 0 while the surfaces overlap, and the surface gap is -overlap.
#pragma once
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
  double inertia_i = 0.0, inertia_j = 0.0;  // moments of inertia (0 for a wall)
  double mass_i = 0.0, mass_j = 0.0;        // masses (0 for a wall)
  Vec3 v_rel;                               // velocity of i's contact point relative to j's
  double overlap_rate = 0.0;                // d(delta_n)/dt = -v_rel . n
  Vec3 v_t;                                 // tangential part of v_rel
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
  double radius = 0.0, mass = 0.0, inertia = 0.0;
};

// Particle i against particle j (centres closer than R_i + R_j + some reach; dist > 0).
ContactGeometry pair_geometry(const BodyState& i, const BodyState& j);
// Particle i against a wall surface point p with outward normal n (towards the particle side),
// the wall moving with velocity v_wall. `distance` is the centre-to-surface distance along n.
ContactGeometry wall_geometry(const BodyState& i, const Vec3& n, double distance,
                              const Vec3& v_wall);

}  // namespace silodem
