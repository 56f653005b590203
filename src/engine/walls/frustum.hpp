// SPDX-License-Identifier: MIT
// Axisymmetric walls about a vertical axis through (cx, cy), described in the meridian plane
// (r, z). A frustum face is the surface swept by the segment (r0, z0) -> (r1, z1) (a cylinder
// when r0 == r1, a disk when z0 == z1); it acts only where the particle projects onto the segment,
// so it has no phantom extension beyond its ends. Ends that a particle can touch from the inside
// (the outlet rim, any convex bend) are circle edges, a wall of their own.
#pragma once
#include <vector>

#include "engine/walls/wall.hpp"

namespace silodem {

struct Meridian {
  double r = 0.0, z = 0.0;
};

class FrustumFace final : public Wall {
 public:
  // `inner`: particles are on the axis side of the surface (inside a silo).
  FrustumFace(double cx, double cy, Meridian a, Meridian b, bool inner);
  // A thin sheet (the silo's cone): both sides are surfaces, and a centre behind the face is
  // pushed away from its back. With a circle edge at a free end this makes the wall a sheet with
  // a rounded end, whose distance field is continuous all round the end: a particle that goes
  // round the outlet rim meets the edge, then the cone's outer side, never a gap or a jump. A
  // one-sided face (the default) pushes a centre behind it back to its front side.
  FrustumFace& two_sided(bool on) {
    two_sided_ = on;
    return *this;
  }
  bool near(const Vec3& c, double limit, WallHit& hit) const override;
  bool may_touch(const Vec3& c, double limit) const override;
  std::string describe() const override;

 private:
  double cx_, cy_;
  Meridian a_;
  double ur_, uz_, len_;  // unit direction a -> b and length
  double nr_, nz_;        // unit normal towards the particle side
  bool two_sided_ = false;
};

class CircleEdge final : public Wall {
 public:
  // The circle of radius `radius` at height z about the axis. A particle feels it only inside the
  // edge's own region: for every adjacent face, given by its unit direction (dr, dz) pointing away
  // from the edge along that face, the particle must lie behind the face's end.
  CircleEdge(double cx, double cy, Meridian at, std::vector<Meridian> adjacent_directions);
  bool near(const Vec3& c, double limit, WallHit& hit) const override;
  bool may_touch(const Vec3& c, double limit) const override;
  std::string describe() const override;

 private:
  double cx_, cy_;
  Meridian at_;
  std::vector<Meridian> adjacent_;
};

}  // namespace silodem
