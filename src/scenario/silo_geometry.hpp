// SPDX-License-Identifier: MIT
// The laboratory silo (PHYSICS.md 5): a conical hopper from the outlet (z = 0) up to the cylinder,
// a cylinder above it, the outlet rim as an edge, and a valve plate under the outlet. Axis z,
// centred at x = y = 0.
#pragma once
#include <memory>
#include <vector>

#include "core/schema.hpp"
#include "core/vec3.hpp"
#include "engine/walls/wall.hpp"

namespace silodem {

// The silo's surfaces, by name (lost.csv says which one a lost particle was nearest to).
enum class SiloSurface { Cone, Cylinder, OutletPlane, Valve };
const char* surface_name(SiloSurface s);  // "cone", "cylinder", "outlet_plane", "valve"

struct SurfaceDistance {
  SiloSurface surface = SiloSurface::Cone;
  // From the centre to the nearest point of the surface (m): positive on the silo's side (inside
  // the cone or cylinder, above the outlet plane or the valve), negative behind it.
  double distance = 0.0;
};

struct SiloGeometry {
  double outlet_diameter = 0.050;    // m
  double cone_height = 0.633;        // m
  double cylinder_diameter = 0.468;  // m
  double cylinder_height = 0.318;    // m (paper: 951 mm in all)
  double valve_gap = 0.0;            // m, plate below the outlet plane

  double outlet_radius() const { return 0.5 * outlet_diameter; }
  double top_radius() const { return 0.5 * cylinder_diameter; }
  double total_height() const { return cone_height + cylinder_height; }
  double half_angle() const;         // rad, cone half-angle from the vertical
  double radius_at(double z) const;  // wall radius at height z (outlet radius below z = 0)
  // Volume inside the walls between heights z0 < z1 (>= 0).
  double volume(double z0, double z1) const;
  // The surface nearest to the point x, of: the cone and cylinder faces (finite segments in the
  // meridian plane), the outlet opening (the disk z = 0, r <= outlet radius) and, if
  // `valve_closed`, the valve plate (the plane z = -valve_gap). Ties go to that order.
  SurfaceDistance nearest_surface(const Vec3& x, bool valve_closed) const;
};

struct SiloWalls {
  WallList walls;
  std::size_t valve_index = 0;  // index of the valve plate in `walls`
};

// Cone face, cylinder face, outlet-rim edge and valve plate.
SiloWalls make_silo_walls(const SiloGeometry& g);

// The [silo] keys, bound to SiloGeometry's members (defaults: the paper's silo, above).
const std::vector<Bound<SiloGeometry>>& silo_fields();

}  // namespace silodem
