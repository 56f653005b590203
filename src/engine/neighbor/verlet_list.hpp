// SPDX-License-Identifier: MIT
// Verlet neighbour list with a skin, and the contact history stored beside it (no hashing in the
// force loop). Pairs are a half list (j > i) in CSR form; particle-wall candidates likewise.
// Rebuilt only when some particle has moved more than skin/2 since the last build, or when the
// particle set or the walls changed. History is carried over by stable particle ids, so it
// survives rebuilds and particle removal.
#pragma once
#include <cstdint>
#include <vector>

#include "engine/neighbor/cell_grid.hpp"
#include "engine/particle_store.hpp"
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
    return norm2(x - x_at_build_[i]) > 0.25 * skin * skin;  // more than skin / 2
  }
  // Save the current history keyed by ids (call before particles are removed or reordered).
  void stash_history(const ParticleStore& p);
  // Checkpoint: the list as built (its pair order fixes the force summation order, so a resumed
  // run continues bit for bit), the history, and the positions at the build.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

  std::vector<int> offset, partner;  // pairs of i: partner[offset[i] .. offset[i+1])
  std::vector<ContactState> state;
  std::vector<int> wall_offset, wall;  // wall candidates of i
  std::vector<ContactState> wall_state;
  long builds = 0;
  double skin = 0.0;
  int threads = 1;  // OpenMP threads for building and checking

 private:
  struct Saved {
    std::uint64_t a, b;  // pair: ids with a < b, state oriented as "a relative to b";
    ContactState s;      // wall: a = particle id, b = wall index
  };
  std::vector<Saved> saved_pairs_, saved_walls_;
  bool stashed_ = false;
  std::vector<Vec3> x_at_build_;
  CellGrid grid_;
};

}  // namespace silodem
