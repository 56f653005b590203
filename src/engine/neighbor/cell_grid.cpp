// SPDX-License-Identifier: MIT
#include "engine/neighbor/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace silodem {

void CellGrid::build(const std::vector<Vec3>& x, double min_cell, std::size_t max_cells,
                     const PeriodicBox& box) {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& p : x) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  if (x.empty()) lo = hi = Vec3{};
  cell_ = min_cell;
  auto cells_for = [&](const Vec3& a, const Vec3& b) {
    const Vec3 e = b - a;
    return (e.x / cell_ + 1) * (e.y / cell_ + 1) * (e.z / cell_ + 1);
  };
  if (cells_for(lo, hi) > double(max_cells) && x.size() > 16) {
    // A few stray particles far away (flying off, escaping) must neither exhaust memory nor
    // turn the search quadratic: the grid covers the bulk (0.1% to 99.9% per axis) and the
    // rest is clamped into its border cells, which keeps neighbouring points in neighbouring
    // cells.
    std::vector<double> c(x.size());
    auto quantile_box = [&](double Vec3::*axis, double& a, double& b) {
      for (std::size_t i = 0; i < x.size(); ++i) c[i] = x[i].*axis;
      const std::size_t k = x.size() / 1000;
      std::nth_element(c.begin(), c.begin() + long(k), c.end());
      a = c[k] - cell_;
      std::nth_element(c.begin(), c.begin() + long(x.size() - 1 - k), c.end());
      b = c[x.size() - 1 - k] + cell_;
    };
    quantile_box(&Vec3::x, lo.x, hi.x);
    quantile_box(&Vec3::y, lo.y, hi.y);
    quantile_box(&Vec3::z, lo.z, hi.z);
  }
  // A periodic axis: the grid spans the period with a whole number of cells, none shorter than
  // cell_ (so the 27 cells still hold every neighbour).
  double* lo_a[3] = {&lo.x, &lo.y, &lo.z};
  for (int a = 0; a < 3; ++a) {
    periodic_[a] = box.on[a];
    if (box.on[a]) *lo_a[a] = box.lo[a];
  }
  lo_ = lo;
  const Vec3 ext = hi - lo;
  const double ext_a[3] = {ext.x, ext.y, ext.z};
  for (;;) {
    for (int a = 0; a < 3; ++a) {
      if (periodic_[a]) {
        dims_[std::size_t(a)] = std::max(1, static_cast<int>(box.len[a] / cell_));
        edge_[a] = box.len[a] / dims_[std::size_t(a)];
      } else {
        dims_[std::size_t(a)] = std::max(1, static_cast<int>(ext_a[a] / cell_) + 1);
        edge_[a] = cell_;
      }
    }
    const double n = double(dims_[0]) * dims_[1] * dims_[2];
    if (n <= double(max_cells)) break;
    cell_ *= std::cbrt(n / double(max_cells)) * 1.01;
  }
  const int ncell = dims_[0] * dims_[1] * dims_[2];
  start_.assign(ncell + 1, 0);
  cell_of_particle_.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto c = cell_of(x[i]);
    cell_of_particle_[i] = cell_index(c[0], c[1], c[2]);
    ++start_[cell_of_particle_[i] + 1];
  }
  for (int c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  order_.resize(x.size());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < x.size(); ++i) order_[fill[cell_of_particle_[i]]++] = int(i);
}

std::array<int, 3> CellGrid::cell_of(const Vec3& p) const {
  auto clampi = [](double v, int n) { return std::clamp(static_cast<int>(v), 0, n - 1); };
  return {clampi((p.x - lo_.x) / edge_[0], dims_[0]), clampi((p.y - lo_.y) / edge_[1], dims_[1]),
          clampi((p.z - lo_.z) / edge_[2], dims_[2])};
}

}  // namespace silodem
