// SPDX-License-Identifier: MIT
#include "engine/walls/frustum.hpp"

#include <fmt/format.h>
#include <cmath>

namespace silodem {
namespace {

// Radial unit vector and radius of c about the axis; on the axis any direction will do.
void radial(double cx, double cy, const Vec3& c, double& r, double& ex, double& ey) {
  const double dx = c.x - cx, dy = c.y - cy;
  r = std::sqrt(dx * dx + dy * dy);
  if (r > 0.0) {
    ex = dx / r, ey = dy / r;
  } else {
    ex = 1.0, ey = 0.0;
  }
}

}  // namespace

FrustumFace::FrustumFace(double cx, double cy, Meridian a, Meridian b, bool inner)
    : cx_(cx), cy_(cy), a_(a) {
  const double dr = b.r - a.r, dz = b.z - a.z;
  len_ = std::sqrt(dr * dr + dz * dz);
  ur_ = dr / len_, uz_ = dz / len_;
  // Normal: the direction rotated by -90 deg points to smaller r for an upward segment.
  nr_ = -uz_, nz_ = ur_;
  if (!inner) nr_ = -nr_, nz_ = -nz_;
}

bool FrustumFace::near(const Vec3& c, double limit, WallHit& hit) const {
  double r, ex, ey;
  radial(cx_, cy_, c, r, ex, ey);
  const double mr = r - a_.r, mz = c.z - a_.z;
  const double t = mr * ur_ + mz * uz_;
  if (t < 0.0 || t > len_) return false;  // beyond the ends: not this face
  const double dist = mr * nr_ + mz * nz_;
  // A centre more than `limit` behind the surface is not in contact (it escaped).
  if (dist >= limit || dist <= -limit) return false;
  // Behind the face near a free end a: the back acts, its normal pointing away from it.
  const double s = back_at_a_ && dist < 0.0 && t < 2.0 * limit ? -1.0 : 1.0;
  hit.n = {s * nr_ * ex, s * nr_ * ey, s * nz_};
  hit.distance = s * dist;
  return true;
}

bool FrustumFace::may_touch(const Vec3& c, double limit) const {
  double r, ex, ey;
  radial(cx_, cy_, c, r, ex, ey);
  const double mr = r - a_.r, mz = c.z - a_.z;
  const double t = mr * ur_ + mz * uz_;
  const double dist = mr * nr_ + mz * nz_;
  return t >= -limit && t <= len_ + limit && dist < limit && dist >= -limit;
}

std::string FrustumFace::describe() const {
  return fmt::format("frustum face from (r {:g}, z {:g}) over {:g} m", a_.r, a_.z, len_);
}

CircleEdge::CircleEdge(double cx, double cy, Meridian at, std::vector<Meridian> adjacent)
    : cx_(cx), cy_(cy), at_(at), adjacent_(std::move(adjacent)) {}

bool CircleEdge::near(const Vec3& c, double limit, WallHit& hit) const {
  double r, ex, ey;
  radial(cx_, cy_, c, r, ex, ey);
  const double mr = r - at_.r, mz = c.z - at_.z;
  for (const Meridian& u : adjacent_)
    if (mr * u.r + mz * u.z >= 0.0) return false;  // beside an adjacent face: the face acts
  const double dist = std::sqrt(mr * mr + mz * mz);
  if (dist >= limit || dist == 0.0) return false;
  hit.n = {mr / dist * ex, mr / dist * ey, mz / dist};
  hit.distance = dist;
  return true;
}

bool CircleEdge::may_touch(const Vec3& c, double limit) const {
  double r, ex, ey;
  radial(cx_, cy_, c, r, ex, ey);
  return std::hypot(r - at_.r, c.z - at_.z) < limit;
}

std::string CircleEdge::describe() const {
  return fmt::format("circle edge of radius {:g} at z {:g}", at_.r, at_.z);
}

namespace {

std::vector<Field> frustum_fields() {
  return {Field::vec3("axis", "a point on the vertical axis (x, y used)", "m"),
          Field::number("z0", "lower end height", "m").needed(),
          Field::number("r0", "radius at z0", "m").needed().at_least(0),
          Field::number("z1", "upper end height", "m").needed(),
          Field::number("r1", "radius at z1", "m").needed().at_least(0),
          Field::flag("inner", "particles inside (on the axis side)", true)};
}
WallList make_frustum(const ParamValues& v) {
  if (v.number("z1") <= v.number("z0")) throw v.error("z1", "must be above z0");
  WallList w;
  const Vec3 a = v.vector("axis");
  w.push_back(std::make_unique<FrustumFace>(a.x, a.y, Meridian{v.number("r0"), v.number("z0")},
                                            Meridian{v.number("r1"), v.number("z1")},
                                            v.flag("inner")));
  return w;
}

std::vector<Field> cylinder_fields() {
  return {Field::vec3("axis", "a point on the vertical axis (x, y used)", "m"),
          Field::number("radius", "radius", "m").needed().above(0),
          Field::number("z0", "lower end", "m").needed(),
          Field::number("z1", "upper end", "m").needed(),
          Field::flag("inner", "particles inside", true)};
}
WallList make_cylinder(const ParamValues& v) {
  if (v.number("z1") <= v.number("z0")) throw v.error("z1", "must be above z0");
  WallList w;
  const Vec3 a = v.vector("axis");
  const double r = v.number("radius");
  w.push_back(std::make_unique<FrustumFace>(a.x, a.y, Meridian{r, v.number("z0")},
                                            Meridian{r, v.number("z1")}, v.flag("inner")));
  return w;
}

}  // namespace

WallEntry frustum_wall_entry() {
  return {"frustum", "conical face between two radii about a vertical axis (no phantom extension)",
          &frustum_fields, &make_frustum};
}
WallEntry cylinder_wall_entry() {
  return {"cylinder", "vertical cylindrical face between two heights", &cylinder_fields,
          &make_cylinder};
}

}  // namespace silodem
