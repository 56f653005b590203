// SPDX-License-Identifier: MIT
#include "engine/neighbor/verlet_list.hpp"

#include <algorithm>

namespace silodem {
namespace {

bool nonzero(const ContactState& s) {
  return norm2(s.tangential) > 0.0 || norm2(s.rolling) > 0.0;
}
ContactState flipped(const ContactState& s) {
  return {-s.tangential, -s.rolling};
}
bool key_less(std::uint64_t a1, std::uint64_t b1, std::uint64_t a2, std::uint64_t b2) {
  return a1 != a2 ? a1 < a2 : b1 < b2;
}

}  // namespace

void VerletList::stash_history(const ParticleStore& p) {
  // Already stashed since the last build (e.g. two removals in one step): the list no longer
  // matches the particle indices, and the stash already holds everything.
  if (stashed_) return;
  saved_pairs_.clear();
  saved_walls_.clear();
  const std::size_t n = offset.empty() ? 0 : offset.size() - 1;
  // Exact sizes first: the stash exists beside the list during a rebuild, so it sets the peak
  // memory (a doubling vector would hold up to twice what it needs).
  std::size_t pairs = 0, walls = 0;
  for (const auto& s : state) pairs += nonzero(s) ? 1 : 0;
  for (const auto& s : wall_state) walls += nonzero(s) ? 1 : 0;
  saved_pairs_.reserve(pairs);
  saved_walls_.reserve(walls);
  for (std::size_t i = 0; i < n; ++i) {
    for (int e = offset[i]; e < offset[i + 1]; ++e) {
      if (!nonzero(state[e])) continue;
      const std::uint64_t a = p.id[i], b = p.id[partner[e]];
      if (a < b)
        saved_pairs_.push_back({a, b, state[e]});
      else
        saved_pairs_.push_back({b, a, flipped(state[e])});
    }
    for (int e = wall_offset[i]; e < wall_offset[i + 1]; ++e)
      if (nonzero(wall_state[e]))
        saved_walls_.push_back({p.id[i], std::uint64_t(wall[e]), wall_state[e]});
  }
  auto less = [](const Saved& l, const Saved& r) { return key_less(l.a, l.b, r.a, r.b); };
  std::sort(saved_pairs_.begin(), saved_pairs_.end(), less);
  std::sort(saved_walls_.begin(), saved_walls_.end(), less);
  stashed_ = true;
}

void VerletList::build(const ParticleStore& p, const WallList& walls, double skin_,
                       double reach_over_d) {
  if (!stashed_) stash_history(p);
  skin = skin_;
  const std::size_t n = p.size();
  double r_max = 0.0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  const double cut_max = 2.0 * r_max * (1.0 + reach_over_d) + skin;
  grid_.build(p.x, cut_max, 8 * n + 64);

  // Two passes over i (count, then fill) give a CSR list whose order depends only on the
  // particle order, not on the thread count.
  std::vector<int> count(n + 1, 0);
  auto visit = [&](std::size_t i, auto&& emit) {
    grid_.for_each_near(p.x[i], [&](int j) {
      if (j <= int(i)) return;
      const double cut = (p.radius[i] + p.radius[j]) * (1.0 + reach_over_d) + skin;
      if (norm2(p.x[i] - p.x[j]) < cut * cut) emit(j);
    });
  };
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    int c = 0;
    visit(i, [&](int) { ++c; });
    count[i + 1] = c;
  }
  offset.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + count[i + 1];
  partner.assign(offset[n], 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<int> mine;
    visit(i, [&](int j) { mine.push_back(j); });
    std::sort(mine.begin(), mine.end());  // cell order is arbitrary; index order is canonical
    std::copy(mine.begin(), mine.end(), partner.begin() + offset[i]);
  }

  // Wall candidates.
  std::vector<int> wcount(n + 1, 0);
  const double w_skin = skin;
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    const double limit = p.radius[i] * (1.0 + 2.0 * reach_over_d) + w_skin;
    int c = 0;
    for (const auto& w : walls) c += (w->enabled && w->may_touch(p.x[i], limit)) ? 1 : 0;
    wcount[i + 1] = c;
  }
  wall_offset.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) wall_offset[i + 1] = wall_offset[i] + wcount[i + 1];
  wall.assign(wall_offset[n], 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    const double limit = p.radius[i] * (1.0 + 2.0 * reach_over_d) + w_skin;
    int e = wall_offset[i];
    for (std::size_t k = 0; k < walls.size(); ++k)
      if (walls[k]->enabled && walls[k]->may_touch(p.x[i], limit)) wall[e++] = int(k);
  }

  // Re-attach the history by stable ids.
  state.assign(partner.size(), ContactState{});
  wall_state.assign(wall.size(), ContactState{});
  if (!saved_pairs_.empty() || !saved_walls_.empty()) {
    auto find = [](const std::vector<Saved>& v, std::uint64_t a, std::uint64_t b) -> const Saved* {
      auto it = std::lower_bound(
          v.begin(), v.end(), Saved{a, b, {}},
          [](const Saved& l, const Saved& r) { return key_less(l.a, l.b, r.a, r.b); });
      return (it != v.end() && it->a == a && it->b == b) ? &*it : nullptr;
    };
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 256)
    for (std::size_t i = 0; i < n; ++i) {
      for (int e = offset[i]; e < offset[i + 1]; ++e) {
        const std::uint64_t a = p.id[i], b = p.id[partner[e]];
        if (const Saved* s = a < b ? find(saved_pairs_, a, b) : find(saved_pairs_, b, a))
          state[e] = a < b ? s->s : flipped(s->s);
      }
      for (int e = wall_offset[i]; e < wall_offset[i + 1]; ++e)
        if (const Saved* s = find(saved_walls_, p.id[i], std::uint64_t(wall[e])))
          wall_state[e] = s->s;
    }
  }
  std::vector<Saved>().swap(saved_pairs_);  // release: the stash lives only during a rebuild
  std::vector<Saved>().swap(saved_walls_);
  stashed_ = false;
  x_at_build_ = p.x;
  ++builds;
}

bool VerletList::needs_rebuild(const ParticleStore& p) const {
  if (!built_for(p.size())) return true;
  const std::size_t n = p.size();
  int moved = 0;
#pragma omp parallel for schedule(static) reduction(| : moved) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) moved |= moved_far(i, p.x[i]) ? 1 : 0;
  return moved != 0;
}

void VerletList::save(ByteWriter& w) const {
  w.tag("LIST");
  w.put(offset), w.put(partner), w.put(state), w.put(wall_offset), w.put(wall), w.put(wall_state);
  w.put(builds), w.put(skin), w.put(x_at_build_);
  w.put(std::uint8_t(stashed_)), w.put(saved_pairs_), w.put(saved_walls_);
}

void VerletList::load(ByteReader& r) {
  r.tag("LIST");
  r.get(offset), r.get(partner), r.get(state), r.get(wall_offset), r.get(wall), r.get(wall_state);
  r.get(builds), r.get(skin), r.get(x_at_build_);
  stashed_ = r.get<std::uint8_t>() != 0;
  r.get(saved_pairs_), r.get(saved_walls_);
}

}  // namespace silodem
