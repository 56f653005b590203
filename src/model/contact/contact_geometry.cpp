// SPDX-License-Identifier: MIT
#include "model/contact/contact_geometry.hpp"

#include <cmath>

namespace silodem {

static void finish_kinematics(ContactGeometry& g, const Vec3& v_i, const Vec3& v_j) {
  // Contact-point velocities: v + omega x r, with r = -arm_i n for i and +arm_j n for j.
  const Vec3 vc_i = v_i + cross(g.omega_i, -g.arm_i * g.n);
  const Vec3 vc_j = v_j + cross(g.omega_j, g.arm_j * g.n);
  g.v_rel = vc_i - vc_j;
  const double vn = dot(g.v_rel, g.n);
  g.overlap_rate = -vn;
  g.v_t = g.v_rel - vn * g.n;
}

ContactGeometry pair_geometry(const BodyState& i, const BodyState& j) {
  ContactGeometry g;
  const Vec3 d = i.x - j.x;
  const double dist = norm(d);
  g.n = d / dist;
  g.overlap = i.radius + j.radius - dist;
  // Contact point on the radical plane (MFIX DIST_CL / DIST_CI): arm_i^2 - a^2 = R_i^2 ...
  g.arm_i = 0.5 * dist + (i.radius * i.radius - j.radius * j.radius) / (2.0 * dist);
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
  g.omega_i = i.omega;
  g.omega_j = j.omega;
  finish_kinematics(g, i.v, j.v);
  return g;
}

ContactGeometry wall_geometry(const BodyState& i, const Vec3& n, double distance,
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
  g.omega_i = i.omega;
  finish_kinematics(g, i.v, v_wall);
  return g;
}

}  // namespace silodem
