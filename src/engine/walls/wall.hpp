// SPDX-License-Identifier: MIT
// A wall is a surface that can tell, for a sphere centre, the nearest surface point's normal and
// distance. New shapes: one file in walls/ plus one line in walls/registry.cpp.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/schema.hpp"
#include "core/vec3.hpp"

namespace silodem {

struct WallHit {
  Vec3 n;                 // unit normal from the surface towards the centre
  double distance = 0.0;  // centre-to-surface distance along n (negative: centre behind it)
};

class Wall {
 public:
  virtual ~Wall() = default;
  // True (and `hit` filled) when the centre is closer than `limit` to the surface.
  virtual bool near(const Vec3& centre, double limit, WallHit& hit) const = 0;
  // Candidate test of the neighbour list: true if the wall may touch a sphere whose centre stays
  // within `limit` of c. Must not apply region restrictions that a particle can cross between two
  // list builds (face ends, edge regions); the default is `near`.
  virtual bool may_touch(const Vec3& c, double limit) const {
    WallHit hit;
    return near(c, limit, hit);
  }
  virtual std::string describe() const = 0;
  // A wall that can move (a driven plate, engine/plate.hpp) says so and moves by `d`; the others
  // throw std::logic_error.
  virtual bool movable() const { return false; }
  virtual void translate(const Vec3& /*d*/) {
    throw std::logic_error("this wall cannot move: " + describe());
  }
  // The velocity its contacts see (m/s); a wall that moves sets it as it moves.
  Vec3 velocity() const { return velocity_; }
  void set_velocity(const Vec3& v) { velocity_ = v; }
  bool enabled = true;  // a disabled wall (an opened valve) takes part in no contact

 private:
  Vec3 velocity_;
};

using WallList = std::vector<std::unique_ptr<Wall>>;

struct WallEntry {
  const char* name;
  const char* summary;
  std::vector<Field> (*fields)();
  // A wall entry may produce several surfaces (a box is six planes).
  WallList (*make)(const ParamValues& values);
};

const std::vector<WallEntry>& wall_types();
const WallEntry* find_wall_type(const std::string& name);

}  // namespace silodem
