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

const char* surface_name(SiloSurface s) {
  switch (s) {
    case SiloSurface::Cone:
      return "cone";
    case SiloSurface::Cylinder:
      return "cylinder";
    case SiloSurface::OutletPlane:
      return "outlet_plane";
    case SiloSurface::Valve:
      return "valve";
  }
  return "?";
}

namespace {

// Signed distance from (r, z) to the meridian segment a -> b whose inside (the axis side for an
// upward segment) is on the left of a -> b: the distance to the segment's nearest point, with
// the sign of the side of its line.
double segment_distance(double r, double z, double ar, double az, double br, double bz) {
  const double ur = br - ar, uz = bz - az, len2 = ur * ur + uz * uz;
  const double s = std::clamp(((r - ar) * ur + (z - az) * uz) / len2, 0.0, 1.0);
  const double d = std::hypot(r - (ar + s * ur), z - (az + s * uz));
  const double side = (r - ar) * -uz + (z - az) * ur;  // > 0: inside
  return side < 0.0 ? -d : d;
}

}  // namespace

SurfaceDistance SiloGeometry::nearest_surface(const Vec3& x, bool valve_closed) const {
  const double r = std::hypot(x.x, x.y), R0 = outlet_radius(), R1 = top_radius();
  SurfaceDistance best{SiloSurface::Cone, segment_distance(r, x.z, R0, 0.0, R1, cone_height)};
  auto consider = [&](SiloSurface s, double d) {
    if (std::fabs(d) < std::fabs(best.distance)) best = {s, d};
  };
  if (cylinder_height > 0.0)
    consider(SiloSurface::Cylinder, segment_distance(r, x.z, R1, cone_height, R1, total_height()));
  // The opening: above it is inside the silo, below it is out.
  const double to_disk = r <= R0 ? std::fabs(x.z) : std::hypot(r - R0, x.z);
  consider(SiloSurface::OutletPlane, x.z < 0.0 ? -to_disk : to_disk);
  if (valve_closed) consider(SiloSurface::Valve, x.z + valve_gap);
  return best;
}

SiloWalls make_silo_walls(const SiloGeometry& g) {
  SiloWalls s;
  const Meridian rim{g.outlet_radius(), 0.0}, joint{g.top_radius(), g.cone_height},
      top{g.top_radius(), g.total_height()};
  auto cone = std::make_unique<FrustumFace>(0.0, 0.0, rim, joint, true);
  // The cone is a thin sheet: a particle that went out through the outlet and round the rim
  // meets its outer side (docs/models/silo.md).
  cone->back_at_a(true);
  const Meridian u = cone->direction();
  s.walls.push_back(std::move(cone));
  if (g.cylinder_height > 0.0)  // no cylinder: no zero-length face
    s.walls.push_back(std::make_unique<FrustumFace>(0.0, 0.0, joint, top, true));
  // The rim is a convex edge seen from the outlet: it acts where the cone face does not, i.e.
  // behind the face's lower end. The cone/cylinder joint is concave from the inside: the two faces
  // cover it, with no edge of its own.
  s.walls.push_back(std::make_unique<CircleEdge>(0.0, 0.0, rim, std::vector<Meridian>{u}));
  s.valve_index = s.walls.size();
  s.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, -g.valve_gap}, Vec3{0, 0, 1}));
  return s;
}

const std::vector<Bound<SiloGeometry>>& silo_fields() {
  using F = Field;
  using S = SiloGeometry;
  static const std::vector<Bound<S>> b = {
      bind(
          F::number("outlet_diameter_mm", "outlet diameter", "mm", units::mm).above(0).at_most(1e4),
          &S::outlet_diameter),
      bind(F::number("cone_height_mm", "height of the conical hopper", "mm", units::mm)
               .above(0)
               .at_most(1e5),
           &S::cone_height),
      bind(F::number("cylinder_diameter_mm", "diameter of the cylinder (top of the cone)", "mm",
                     units::mm)
               .above(0)
               .at_most(1e5),
           &S::cylinder_diameter),
      bind(F::number("cylinder_height_mm", "height of the cylinder above the cone", "mm", units::mm)
               .at_least(0)
               .at_most(1e5),
           &S::cylinder_height),
      bind(
          F::number("valve_gap_mm", "distance of the valve plate below the outlet", "mm", units::mm)
              .at_least(0)
              .at_most(1e3),
          &S::valve_gap),
  };
  return b;
}

}  // namespace silodem
