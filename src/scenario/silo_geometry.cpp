// SPDX-License-Identifier: MIT
#include "scenario/silo_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "engine/walls/frustum.hpp"
#include "engine/walls/plane.hpp"

namespace silodem {

double SiloGeometry::half_angle() const {
  return std::atan((top_radius() - outlet_radius()) / cone_height);
}

double SiloGeometry::radius_at(double z) const {
  if (z <= 0.0) return outlet_radius();
  if (z >= cone_height) return top_radius();
  return outlet_radius() + (top_radius() - outlet_radius()) * z / cone_height;
}

double SiloGeometry::volume(double z0, double z1) const {
  // Frustum pieces: V = pi h / 3 (R0^2 + R0 R1 + R1^2) on each side of the cone/cylinder joint.
  auto piece = [&](double a, double b) {
    if (b <= a) return 0.0;
    const double r0 = radius_at(a), r1 = radius_at(b);
    return kPi * (b - a) / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
  };
  const double joint = cone_height;
  return piece(std::max(z0, 0.0), std::min(z1, joint)) + piece(std::max(z0, joint), z1);
}

SiloWalls make_silo_walls(const SiloGeometry& g) {
  SiloWalls s;
  const Meridian rim{g.outlet_radius(), 0.0}, joint{g.top_radius(), g.cone_height},
      top{g.top_radius(), g.total_height()};
  auto cone = std::make_unique<FrustumFace>(0.0, 0.0, rim, joint, true);
  cone->free_ends(true, false);  // the rim is a free edge, the joint is not
  s.walls.push_back(std::move(cone));
  if (g.cylinder_height > 0.0)  // no cylinder: no zero-length face
    s.walls.push_back(std::make_unique<FrustumFace>(0.0, 0.0, joint, top, true));
  // The rim is a convex edge seen from the outlet: it acts where the cone face does not, i.e.
  // behind the face's lower end. The cone/cylinder joint is concave from the inside: the two faces
  // cover it, with no edge of its own.
  const double len = std::hypot(joint.r - rim.r, joint.z - rim.z);
  s.walls.push_back(std::make_unique<CircleEdge>(
      0.0, 0.0, rim, std::vector<Meridian>{{(joint.r - rim.r) / len, (joint.z - rim.z) / len}}));
  s.valve_index = s.walls.size();
  s.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, -g.valve_gap}, Vec3{0, 0, 1}));
  return s;
}

}  // namespace silodem
