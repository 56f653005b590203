// SPDX-License-Identifier: MIT
// Simulation's contact list: when it is rebuilt, the Morton reorder of the particles before a
// build, the removal of particles with their history kept, and the lookup of one contact.
#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "engine/simulation.hpp"

namespace silodem {

void Simulation::update_neighbors(bool moved) {
  if (rebuild_pending_ || moved) {
    if (s_.reorder_every > 0 && list_.builds % s_.reorder_every == 0) reorder_spatially();
    list_.build(p_, walls_, s_.skin, model_.max_reach_over_d());
    rebuild_pending_ = false;
  }
}

namespace {
// Spreads the low 21 bits of v so that two zero bits follow each one.
std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}
}  // namespace

// Particles sorted by the Morton code of a grid of cells one largest diameter wide (ties by id:
// deterministic), so that the partners of i, and the next particles, are mostly in cache. The
// contact history goes through the stash, renumbered; the list is rebuilt right after.
void Simulation::reorder_spatially() {
  const std::size_t n = p_.size();
  if (n < 2) return;
  Vec3 lo = p_.x[0];
  double r_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    lo = {std::min(lo.x, p_.x[i].x), std::min(lo.y, p_.x[i].y), std::min(lo.z, p_.x[i].z)};
    r_max = std::max(r_max, p_.radius[i]);
  }
  const double inv_h = 1.0 / std::max(2.0 * r_max, 1e-12);
  auto cell = [&](double c, double c0) {  // clamped; a non-finite position sorts last
    const double v = (c - c0) * inv_h;
    return v >= 0.0 && v < double(0x1fffff) ? std::uint64_t(v) : std::uint64_t(0x1fffff);
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = p_.x[i];
    key[i] = {
        spread3(cell(x.x, lo.x)) | spread3(cell(x.y, lo.y)) << 1 | spread3(cell(x.z, lo.z)) << 2,
        i};
  }
  std::sort(key.begin(), key.end(), [&](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : p_.id[a.second] < p_.id[b.second];
  });
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = key[k].second;
  list_.stash_history(p_);  // while the list still matches the old order
  p_.permute(order);
  std::vector<int> to(n);
  for (std::size_t k = 0; k < n; ++k) to[order[k]] = int(k);
  list_.renumber(to);
}

void Simulation::remove_particles(std::vector<std::size_t> idx) {
  if (idx.empty()) return;
  // The list is compacted like the particles (it stays valid: removing particles brings no
  // other pair into range). Only a list that was not built for these particles is rebuilt, now:
  // until then its indices would point at the wrong (or no) particles for anyone who reads it
  // (energy(), contact_state(), hooks).
  const bool current = !rebuild_pending_ && list_.built_for(p_.size());
  if (current) {
    const std::vector<int> to = p_.remove_all(std::move(idx));
    if (list_.remove(p_, to)) return;
    throw std::logic_error("Simulation::remove_particles: the list does not match the particles");
  }
  list_.stash_history(p_);
  list_.renumber(p_.remove_all(std::move(idx)));
  list_.build(p_, walls_, s_.skin, model_.max_reach_over_d());
  rebuild_pending_ = false;
  // Forces of the remaining particles still include the removed ones until the next step's
  // force pass; that is the usual sink convention.
}

std::optional<ContactState> Simulation::contact_state(std::uint64_t a, std::uint64_t b,
                                                      bool* flipped) const {
  const long ia = p_.index_of(a), ib = p_.index_of(b);
  if (ia < 0 || ib < 0) return std::nullopt;
  const long lo = std::min(ia, ib), hi = std::max(ia, ib);
  for (int e = list_.offset[lo]; e < list_.offset[lo + 1]; ++e)
    if (list_.partner[e] == hi) {
      if (flipped) *flipped = (lo != ia);
      return list_.state(std::size_t(e));
    }
  return std::nullopt;
}

}  // namespace silodem
