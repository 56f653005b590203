// SPDX-License-Identifier: MIT
// Uniform cell grid over the particles' bounding box (linked cells as sorted arrays): each
// particle's neighbours within `cell_size` lie in its own and the 26 surrounding cells. Along a
// periodic axis the grid spans the period exactly and its cells wrap round.
#pragma once
#include <array>
#include <vector>

#include "core/vec3.hpp"
#include "engine/periodic.hpp"

namespace silodem {

class CellGrid {
 public:
  // Bins the points. The cell size is at least `min_cell`; it grows when the box would need more
  // than about `max_cells` cells (a stray particle far away must not exhaust memory). Along the
  // periodic axes of `box` the points must lie in the box (Simulation wraps them).
  void build(const std::vector<Vec3>& x, double min_cell, std::size_t max_cells,
             const PeriodicBox& box = {});
  std::array<int, 3> cell_of(const Vec3& p) const;
  int cell_index(int cx, int cy, int cz) const { return (cz * dims_[1] + cy) * dims_[0] + cx; }
  const std::array<int, 3>& dims() const { return dims_; }
  // Particles of cell c: order_[start_[c] .. start_[c+1]), ascending index.
  const std::vector<int>& start() const { return start_; }
  const std::vector<int>& order() const { return order_; }
  // The smallest cell edge (periodic axes may have longer cells: a whole number fills the period).
  double cell_size() const { return cell_; }
  // Calls f(j) for every particle j in the cell of p and the 26 cells around it, each cell once
  // (a periodic axis of fewer than three cells has fewer distinct neighbours).
  template <class F>
  void for_each_near(const Vec3& p, F&& f) const {
    const auto c = cell_of(p);
    int near[3][3], count[3];
    for (int a = 0; a < 3; ++a) {
      count[a] = 0;
      if (periodic_[a] && dims_[a] < 3) {
        for (int k = 0; k < dims_[a]; ++k) near[a][count[a]++] = k;
        continue;
      }
      for (int d = -1; d <= 1; ++d) {
        int k = c[std::size_t(a)] + d;
        if (periodic_[a]) k = (k + dims_[a]) % dims_[a];
        if (k >= 0 && k < dims_[a]) near[a][count[a]++] = k;
      }
    }
    for (int iz = 0; iz < count[2]; ++iz)
      for (int iy = 0; iy < count[1]; ++iy)
        for (int ix = 0; ix < count[0]; ++ix) {
          const int cell = cell_index(near[0][ix], near[1][iy], near[2][iz]);
          for (int k = start_[std::size_t(cell)]; k < start_[std::size_t(cell) + 1]; ++k)
            f(order_[std::size_t(k)]);
        }
  }

 private:
  Vec3 lo_;
  double cell_ = 1.0;
  double edge_[3] = {1.0, 1.0, 1.0};  // cell edge per axis
  bool periodic_[3] = {false, false, false};
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_, order_, cell_of_particle_;
};

}  // namespace silodem
