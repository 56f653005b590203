// SPDX-License-Identifier: MIT
// Verlet neighbour list with a skin, and the contact history stored beside it (no hashing in the
// force loop). Pairs are a half list (j > i) in CSR form; particle-wall candidates likewise.
// Rebuilt only when some particle has moved more than skin/2 (or its own allowance, with a skin
// floor below 1) since the last build, or when the particle set or the walls changed. History is
// carried over by particle index: a rebuild merges the old list's nonzero states into the new one
// (both are sorted by (i, j)); when particles are removed or reordered, the caller stashes the
// history first and renumbers it after, so it survives both.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/neighbor/cell_grid.hpp"
#include "engine/particle_store.hpp"
#include "engine/periodic.hpp"
#include "engine/walls/wall.hpp"
#include "model/contact/contact_history.hpp"

namespace silodem {

class VerletList {
 public:
  // reach_over_d: the longest cohesion range beyond contact (fraction of the pair's d_ref).
  void build(const ParticleStore& p, const WallList& walls, double skin, double reach_over_d);
  bool needs_rebuild(const ParticleStore& p) const;
  // The test needs_rebuild makes, for a caller that runs it inside a pass it makes anyway (the
  // integrator): rebuild when !built_for(n) or moved_far(i, x) for some particle.
  bool built_for(std::size_t n) const { return x_at_build_.size() == n; }
  bool moved_far(std::size_t i, const Vec3& x) const {
    const Vec3 d = x - x_at_build_[i];
    // More than the particle's allowance: skin / 2, or its own with a skin floor below 1.
    return norm2(box_.any() ? box_.image(d) : d) > (allow2_.empty() ? allow2_all_ : allow2_[i]);
  }
  // The allowance of particle i (how far it may move before a rebuild), as of the last build.
  double allowance(std::size_t i) const {
    return allow2_.empty() ? 0.5 * skin : std::sqrt(allow2_[i]);
  }
  // Periodic boundaries (before the first build): pairs are found through the nearest image.
  // build() throws SimulationError if a period is shorter than twice the longest cut-off, where
  // one pair would have two images in range.
  void set_periodic(const PeriodicBox& box) { box_ = box; }
  const PeriodicBox& periodic() const { return box_; }
  // Keep the current history aside, by particle index (call before particles are removed or
  // reordered, then renumber() after). Checks that the particles are still the ones the list was
  // built for (throws std::logic_error if they were removed or reordered behind its back).
  void stash_history(const ParticleStore& p);
  // The particles were moved: old index k is now old_to_new[k] (-1: removed). Renumbers the
  // stashed history (its pairs and wall contacts of removed particles are dropped); build() next.
  void renumber(const std::vector<int>& old_to_new);
  // Particles were removed, the others kept in order (old index k is now old_to_new[k], -1:
  // removed; ParticleStore::remove_all): drops their rows and entries and renumbers the rest, with
  // the history beside them and the positions at the build. The list stays valid (a pair it does
  // not hold was out of range at the build and no remaining particle has moved more than its
  // allowance since), so no rebuild is needed; `builds` is unchanged. False, changing nothing, if
  // the list was not built for these particles (then stash_history, renumber and build as before).
  bool remove(const ParticleStore& p, const std::vector<int>& old_to_new);
  // Checkpoint: the list as built (its pair order fixes the force summation order, so a resumed
  // run continues bit for bit), the history, and the positions at the build.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

  std::vector<int> offset, partner;    // pairs of i: partner[offset[i] .. offset[i+1])
  std::vector<int> wall_offset, wall;  // wall candidates of i
  // The history of list pair e and of wall candidate e: the values the contact laws keep,
  // `pair_layout.size` (`wall_layout.size`) doubles per entry, laid out as the laws declare
  // (contact_history.hpp). A run whose laws keep nothing carries no history at all.
  ContactState state(std::size_t e) const { return read(hist, pair_layout.size, e); }
  void set_state(std::size_t e, const ContactState& s) { write(hist, pair_layout.size, e, s); }
  ContactState wall_state(std::size_t e) const { return read(wall_hist, wall_layout.size, e); }
  void set_wall_state(std::size_t e, const ContactState& s) {
    write(wall_hist, wall_layout.size, e, s);
  }
  // The same with the size known when compiling (the force loop's; H = pair_layout.size).
  template <int H>
  ContactState state_n(std::size_t e) const {
    ContactState s;
    for (int k = 0; k < H; ++k) s.h[k] = hist[e * H + std::size_t(k)];
    return s;
  }
  template <int H>
  void set_state_n(std::size_t e, const ContactState& s) {
    for (int k = 0; k < H; ++k) hist[e * H + std::size_t(k)] = s.h[k];
  }
  // Set before the first build or load (Simulation sets them from its contact laws).
  void set_layouts(const StateLayout& pairs, const StateLayout& walls);
  const StateLayout& layout() const { return pair_layout; }
  const StateLayout& layout_walls() const { return wall_layout; }
  std::vector<double> hist, wall_hist;
  long builds = 0;
  double skin = 0.0;
  int threads = 1;  // OpenMP threads for building and checking
  // Per-particle skin (speed only, set before a build; SimulationSettings::skin_floor): 1 gives
  // every particle the allowance skin / 2 (the fixed skin). Below 1, a build gives particle i
  // skin / 2 x min(1, max(skin_floor, 2 |v_i| / v_max)) and lists a pair within
  // (r_i + r_j)(1 + reach) + a_i + a_j: the list stays valid while each particle is within its own
  // allowance, and slow particles list fewer pairs out of range. Wall candidates keep the full
  // skin.
  double skin_floor = 1.0;

 private:
  struct Saved {
    int a, b;        // pair: indices a < b, state oriented as "a relative to b";
    ContactState s;  // wall: a = particle index, b = wall index
  };
  void attach_history(const ParticleStore& p);
  static ContactState read(const std::vector<double>& v, int size, std::size_t e) {
    ContactState s;
    for (int k = 0; k < size; ++k) s.h[k] = v[e * std::size_t(size) + std::size_t(k)];
    return s;
  }
  static void write(std::vector<double>& v, int size, std::size_t e, const ContactState& s) {
    for (int k = 0; k < size; ++k) v[e * std::size_t(size) + std::size_t(k)] = s.h[k];
  }
  StateLayout pair_layout, wall_layout;
  std::vector<Saved> saved_pairs_, saved_walls_;  // sorted by (a, b)
  bool stashed_ = false;
  std::uint64_t ids_hash_ = 0;  // of the particle ids at the build, in index order
  bool check_ids_ = false;      // ids_hash_ is known (false before a build and after load())
  std::vector<Vec3> x_at_build_;
  // Squared allowances of the last build: one per particle (skin floor below 1), or, when empty,
  // allow2_all_ = (skin / 2)^2 for every particle.
  std::vector<double> allow2_;
  double allow2_all_ = 0.0;
  CellGrid grid_;
  PeriodicBox box_;
};

}  // namespace silodem
