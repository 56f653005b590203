// SPDX-License-Identifier: MIT
// Uniform cell grid over the particles' bounding box (linked cells as sorted arrays): each
// particle's neighbours within `cell_size` lie in its own and the 26 surrounding cells.
#pragma once
#include <array>
#include <vector>

#include "core/vec3.hpp"

namespace silodem {

class CellGrid {
 public:
  // Bins the points. The cell size is at least `min_cell`; it grows when the box would need more
  // than about `max_cells` cells (a stray particle far away must not exhaust memory).
  void build(const std::vector<Vec3>& x, double min_cell, std::size_t max_cells);
  std::array<int, 3> cell_of(const Vec3& p) const;
  int cell_index(int cx, int cy, int cz) const { return (cz * dims_[1] + cy) * dims_[0] + cx; }
  const std::array<int, 3>& dims() const { return dims_; }
  // Particles of cell c: order_[start_[c] .. start_[c+1]), ascending index.
  const std::vector<int>& start() const { return start_; }
  const std::vector<int>& order() const { return order_; }
  double cell_size() const { return cell_; }
  // Calls f(j) for every particle j in the cell of p and the 26 cells around it.
  template <class F>
  void for_each_near(const Vec3& p, F&& f) const {
    const auto c = cell_of(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = c[0] + dx, cy = c[1] + dy, cz = c[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx >= dims_[0] || cy >= dims_[1] || cz >= dims_[2])
            continue;
          const int cell = cell_index(cx, cy, cz);
          for (int k = start_[std::size_t(cell)]; k < start_[std::size_t(cell) + 1]; ++k)
            f(order_[std::size_t(k)]);
        }
  }

 private:
  Vec3 lo_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_, order_, cell_of_particle_;
};

}  // namespace silodem
