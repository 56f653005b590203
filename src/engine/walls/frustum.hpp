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
  // End a is a free edge of a thin sheet (the outlet rim, with a circle edge of its own): near it
  // the face's back is a surface too. A centre behind the face that projects within 2 `limit` of
  // end a went out and round the edge, and is pushed away from the back: with the edge, the
  // distance field is continuous all round the end, with no gap and no jump. Further along only
  // a particle pressed through the face can be behind it, and the face pushes it back to its
  // front, as everywhere on a face without a free end.
  FrustumFace& back_at_a(bool on) {
    back_at_a_ = on;
    return *this;
  }
  // Unit direction (dr, dz) from end a to end b: what a circle edge at a takes as its adjacent
  // face, so that the two split the space at exactly the same plane.
  Meridian direction() const { return {ur_, uz_}; }
  bool near(const Vec3& c, double limit, WallHit& hit) const override;
  bool may_touch(const Vec3& c, double limit) const override;
  std::string describe() const override;

 private:
  double cx_, cy_;
  Meridian a_;
  double ur_, uz_, len_;  // unit direction a -> b and length
  double nr_, nz_;        // unit normal towards the particle side
  bool back_at_a_ = false;
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
