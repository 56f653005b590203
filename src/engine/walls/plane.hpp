// SPDX-License-Identifier: MIT
// An infinite plane through `point` whose particle side is along `normal`.
#pragma once
#include "engine/walls/wall.hpp"

namespace silodem {

class PlaneWall final : public Wall {
 public:
  PlaneWall(const Vec3& point, const Vec3& normal);
  bool near(const Vec3& c, double limit, WallHit& hit) const override;
  std::string describe() const override;
  bool movable() const override { return true; }
  void translate(const Vec3& d) override { p_ += d; }
  // Puts the plane through `p` (a checkpoint's position: exactly, not by a translation).
  void place(const Vec3& p) { p_ = p; }
  const Vec3& point() const { return p_; }
  const Vec3& normal() const { return n_; }

 private:
  Vec3 p_, n_;
};

}  // namespace silodem
