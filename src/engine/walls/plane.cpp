// SPDX-License-Identifier: MIT
#include "engine/walls/plane.hpp"

#include <fmt/format.h>

namespace silodem {

PlaneWall::PlaneWall(const Vec3& point, const Vec3& normal)
    : p_(point), n_(normal / norm(normal)) {}

bool PlaneWall::near(const Vec3& c, double limit, WallHit& hit) const {
  const double d = dot(c - p_, n_);
  if (d >= limit) return false;
  hit.n = n_;
  hit.distance = d;
  return true;
}

std::string PlaneWall::describe() const {
  return fmt::format("plane through ({:g}, {:g}, {:g}) with normal ({:.4g}, {:.4g}, {:.4g})", p_.x,
                     p_.y, p_.z, n_.x, n_.y, n_.z);
}

namespace {

std::vector<Field> plane_fields() {
  return {Field::vec3("point", "a point on the plane", "m").needed(),
          Field::vec3("normal", "normal pointing to the particle side").needed()};
}
WallList make_plane(const ParamValues& v) {
  const Vec3 n = v.vector("normal");
  if (norm(n) == 0.0) throw v.error("normal", "must not be the zero vector");
  WallList w;
  w.push_back(std::make_unique<PlaneWall>(v.vector("point"), n));
  return w;
}

std::vector<Field> box_fields() {
  return {Field::vec3("min", "lower corner", "m").needed(),
          Field::vec3("max", "upper corner", "m").needed()};
}
WallList make_box(const ParamValues& v) {
  const Vec3 lo = v.vector("min"), hi = v.vector("max");
  if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
    throw v.error("max", "must be larger than 'min' in x, y and z");
  WallList w;
  w.push_back(std::make_unique<PlaneWall>(lo, Vec3{1, 0, 0}));
  w.push_back(std::make_unique<PlaneWall>(hi, Vec3{-1, 0, 0}));
  w.push_back(std::make_unique<PlaneWall>(lo, Vec3{0, 1, 0}));
  w.push_back(std::make_unique<PlaneWall>(hi, Vec3{0, -1, 0}));
  w.push_back(std::make_unique<PlaneWall>(lo, Vec3{0, 0, 1}));
  w.push_back(std::make_unique<PlaneWall>(hi, Vec3{0, 0, -1}));
  return w;
}

}  // namespace

WallEntry plane_wall_entry() {
  return {"plane", "infinite plane (a floor, a tilted plane)", &plane_fields, &make_plane};
}
WallEntry box_wall_entry() {
  return {"box", "six inward-facing planes of an axis-aligned box", &box_fields, &make_box};
}

}  // namespace silodem
