// SPDX-License-Identifier: MIT
#include "engine/neighbor/verlet_list.hpp"

#include "model/contact/registry.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace silodem {
namespace {

bool key_less(int a1, int b1, int a2, int b2) {
  return a1 != a2 ? a1 < a2 : b1 < b2;
}

std::uint64_t ids_hash(const ParticleStore& p, std::size_t n) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a over whole ids: enough to catch a mix-up
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p.id[i]) * 0x100000001b3ULL;
  return h ^ n;
}

// This thread's share [begin, end) of n particles: contiguous and in thread order, so that the
// buffers concatenate into the list in index order.
std::pair<std::size_t, std::size_t> my_share(std::size_t n) {
#ifdef _OPENMP
  const std::size_t t = std::size_t(omp_get_thread_num()),
                    team = std::size_t(omp_get_num_threads());
#else
  const std::size_t t = 0, team = 1;
#endif
  return {n * t / team, n * (t + 1) / team};
}

}  // namespace

void VerletList::stash_history(const ParticleStore& p) {
  // Already stashed since the last build (e.g. two removals in one step): the list no longer
  // matches the particle indices, and the stash already holds everything.
  if (stashed_) return;
  const std::size_t n = offset.empty() ? 0 : offset.size() - 1;
  if (check_ids_ && (n > p.size() || ids_hash(p, n) != ids_hash_))
    throw std::logic_error(
        "VerletList: particles were removed or reordered without stash_history() and "
        "renumber() (Simulation::remove_particles does both)");
  saved_pairs_.clear();
  saved_walls_.clear();
  // Exact sizes first: the stash exists beside the list during a rebuild, so it sets the peak
  // memory (a doubling vector would hold up to twice what it needs).
  std::size_t pairs = 0, walls = 0;
  if (pair_layout.size > 0)
    for (std::size_t e = 0; e < partner.size(); ++e) pairs += state(e).nonzero() ? 1 : 0;
  if (wall_layout.size > 0)
    for (std::size_t e = 0; e < wall.size(); ++e) walls += wall_state(e).nonzero() ? 1 : 0;
  saved_pairs_.reserve(pairs);
  saved_walls_.reserve(walls);
  // In list order, which is (i, j) order: sorted without sorting.
  for (std::size_t i = 0; i < n && pairs + walls > 0; ++i) {
    for (int e = offset[i]; e < offset[i + 1]; ++e)
      if (const ContactState s = state(std::size_t(e)); s.nonzero())
        saved_pairs_.push_back({int(i), partner[e], s});
    for (int e = wall_offset[i]; e < wall_offset[i + 1]; ++e)
      if (const ContactState s = wall_state(std::size_t(e)); s.nonzero())
        saved_walls_.push_back({int(i), wall[e], s});
  }
  stashed_ = true;
}

namespace {

// Applies old_to_new to a stash sorted by (a, b), in place, and sorts it again if it needs it.
// Entries of removed particles go; a pair whose order turned is swapped and its state turned with
// the layout's factors. The removal of Simulation keeps the others' order, so after it the stash
// is still sorted; a reordering needs the sort.
template <class Saved>
void renumber_stash(std::vector<Saved>& v, const std::vector<int>& to, bool pairs,
                    const StateLayout& layout) {
  auto map = [&](int k) {
    if (k < 0 || std::size_t(k) >= to.size())
      throw std::logic_error("VerletList::renumber: the map does not cover the stash");
    return to[std::size_t(k)];
  };
  std::size_t kept = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Saved s = v[k];
    const int a = map(s.a), b = pairs ? map(s.b) : s.b;
    if (a < 0 || b < 0) continue;
    v[kept++] = (!pairs || a < b) ? Saved{a, b, s.s} : Saved{b, a, layout.swapped(s.s)};
  }
  v.resize(kept);
  auto less = [](const Saved& l, const Saved& r) { return key_less(l.a, l.b, r.a, r.b); };
  if (!std::is_sorted(v.begin(), v.end(), less)) std::sort(v.begin(), v.end(), less);
}

}  // namespace

void VerletList::renumber(const std::vector<int>& old_to_new) {
  if (!stashed_) throw std::logic_error("VerletList::renumber without stash_history");
  renumber_stash(saved_pairs_, old_to_new, /*pairs=*/true, pair_layout);
  renumber_stash(saved_walls_, old_to_new, /*pairs=*/false, wall_layout);
}

void VerletList::build(const ParticleStore& p, const WallList& walls, double skin_,
                       double reach_over_d) {
  if (!stashed_) stash_history(p);
  skin = skin_;
  const std::size_t n = p.size();
  double r_max = 0.0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  const double cut_max = 2.0 * r_max * (1.0 + reach_over_d) + skin;
  for (int a = 0; a < 3; ++a)
    if (box_.on[a] && box_.len[a] < 2.0 * cut_max)
      throw SimulationError(fmt::format(
          "the periodic box is {:.4g} m long along {}: it must be at least twice the neighbour "
          "cut-off, 2 x {:.4g} m (largest diameter with the cohesion range, plus the skin)",
          box_.len[a], "xyz"[a], cut_max));
  grid_.build(p.x, cut_max, 8 * n + 64, box_);

  // The allowances (skin_floor in the header). a_i + a_j is exactly `skin` when both are skin / 2,
  // so a floor of 1 lists what the fixed skin always listed.
  const double half = 0.5 * skin;
  std::vector<double> allow;
  if (skin_floor < 1.0) {
    double v2_max = 0.0;
    for (const Vec3& v : p.v) v2_max = std::max(v2_max, norm2(v));
    const double inv_v_max = v2_max > 0.0 ? 1.0 / std::sqrt(v2_max) : 0.0;
    allow.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      allow[i] = half * std::min(1.0, std::max(skin_floor, 2.0 * norm(p.v[i]) * inv_v_max));
  }
  const bool uniform = allow.empty();

  // One pass over the grid: each thread lists the partners of its share of i, each i's sorted
  // (cell order is arbitrary; index order is canonical), into its own buffer; the buffers then
  // concatenate into the CSR list in thread order. The list depends only on the particle order,
  // not on the thread count.
  const int nt = n > 256 ? std::max(1, threads) : 1;
  std::vector<std::vector<int>> mine(static_cast<std::size_t>(nt));
  offset.assign(n + 1, 0);
#pragma omp parallel num_threads(nt)
  {
    const std::pair<std::size_t, std::size_t> share = my_share(n);
    const std::size_t begin = share.first, end = share.second;
#ifdef _OPENMP
    std::vector<int>& out = mine[std::size_t(omp_get_thread_num())];
#else
    std::vector<int>& out = mine[0];
#endif
    std::vector<int> near;
    for (std::size_t i = begin; i < end; ++i) {
      near.clear();
      const Vec3 xi = p.x[i];
      const double ri = p.radius[i];
      grid_.for_each_near(xi, [&](int j) {
        if (j <= int(i)) return;
        const double cut = (ri + p.radius[j]) * (1.0 + reach_over_d) +
                           (uniform ? skin : allow[i] + allow[std::size_t(j)]);
        const Vec3 d = xi - p.x[j];
        if (norm2(box_.any() ? box_.image(d) : d) < cut * cut) near.push_back(j);
      });
      std::sort(near.begin(), near.end());
      offset[i + 1] = int(near.size());
      out.insert(out.end(), near.begin(), near.end());
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
      partner.resize(std::size_t(offset[n]));
    }
    std::copy(out.begin(), out.end(), partner.begin() + offset[begin]);
  }
  std::vector<std::vector<int>>().swap(mine);

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

  attach_history(p);
  std::vector<Saved>().swap(saved_pairs_);  // release: the stash lives only during a rebuild
  std::vector<Saved>().swap(saved_walls_);
  stashed_ = false;
  check_ids_ = true;
  ids_hash_ = ids_hash(p, n);
  x_at_build_ = p.x;
  allow2_all_ = 0.25 * skin * skin;
  allow2_.resize(allow.size());
  for (std::size_t i = 0; i < allow.size(); ++i) allow2_[i] = allow[i] * allow[i];
  ++builds;
}

// The stash and the new list are both sorted by (i, j) (walls: (i, wall)): one merge walk.
void VerletList::attach_history(const ParticleStore& p) {
  const std::size_t n = p.size();
  hist.assign(partner.size() * std::size_t(pair_layout.size), 0.0);
  wall_hist.assign(wall.size() * std::size_t(wall_layout.size), 0.0);
  if (saved_pairs_.empty() && saved_walls_.empty()) return;
  const int nt = n > 256 ? std::max(1, threads) : 1;
#pragma omp parallel num_threads(nt)
  {
    const std::pair<std::size_t, std::size_t> share = my_share(n);
    const std::size_t begin = share.first, end = share.second;
    auto first = [&](const std::vector<Saved>& v) {
      return std::lower_bound(v.begin(), v.end(), int(begin),
                              [](const Saved& s, int i) { return s.a < i; });
    };
    auto sp = first(saved_pairs_);
    auto sw = first(saved_walls_);
    for (std::size_t i = begin; i < end; ++i) {
      const int ii = int(i);
      for (int e = offset[i]; e < offset[i + 1]; ++e) {
        const int j = partner[e];
        while (sp != saved_pairs_.end() && key_less(sp->a, sp->b, ii, j)) ++sp;
        if (sp != saved_pairs_.end() && sp->a == ii && sp->b == j) set_state(std::size_t(e), sp->s);
      }
      for (int e = wall_offset[i]; e < wall_offset[i + 1]; ++e) {
        const int k = wall[e];
        while (sw != saved_walls_.end() && key_less(sw->a, sw->b, ii, k)) ++sw;
        if (sw != saved_walls_.end() && sw->a == ii && sw->b == k)
          set_wall_state(std::size_t(e), sw->s);
      }
    }
  }
}

bool VerletList::remove(const ParticleStore& p, const std::vector<int>& to) {
  const std::size_t n_old = to.size();
  if (stashed_ || !built_for(n_old) || offset.size() != n_old + 1 ||
      wall_offset.size() != n_old + 1)
    return false;
  // Monotone: new indices in old order, so every row stays sorted and (i < j) stays (i' < j').
  std::size_t n_new = 0;
  for (std::size_t k = 0; k < n_old; ++k)
    if (to[k] >= 0) {
      if (std::size_t(to[k]) != n_new) return false;
      ++n_new;
    }
  if (n_new != p.size()) return false;
  std::size_t w = 0, ww = 0, row = 0;
  int e_begin = 0, we_begin = 0;
  for (std::size_t i = 0; i < n_old; ++i) {
    const int e_end = offset[i + 1], we_end = wall_offset[i + 1];
    if (to[i] >= 0) {
      for (int e = e_begin; e < e_end; ++e) {
        const int j = to[std::size_t(partner[e])];
        if (j < 0) continue;
        partner[w] = j;
        if (pair_layout.size > 0) set_state(w, state(std::size_t(e)));
        ++w;
      }
      for (int e = we_begin; e < we_end; ++e) {
        wall[ww] = wall[std::size_t(e)];
        if (wall_layout.size > 0) set_wall_state(ww, wall_state(std::size_t(e)));
        ++ww;
      }
      x_at_build_[row] = x_at_build_[i];
      if (!allow2_.empty()) allow2_[row] = allow2_[i];
      ++row;
      offset[row] = int(w);
      wall_offset[row] = int(ww);
    }
    e_begin = e_end, we_begin = we_end;
  }
  offset.resize(n_new + 1), wall_offset.resize(n_new + 1), x_at_build_.resize(n_new);
  if (!allow2_.empty()) allow2_.resize(n_new);
  partner.resize(w), wall.resize(ww);
  hist.resize(w * std::size_t(pair_layout.size)),
      wall_hist.resize(ww * std::size_t(wall_layout.size));
  ids_hash_ = ids_hash(p, n_new);
  return true;
}

bool VerletList::needs_rebuild(const ParticleStore& p) const {
  if (!built_for(p.size())) return true;
  const std::size_t n = p.size();
  int moved = 0;
#pragma omp parallel for schedule(static) reduction(| : moved) num_threads(threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) moved |= moved_far(i, p.x[i]) ? 1 : 0;
  return moved != 0;
}

void VerletList::set_layouts(const StateLayout& pairs, const StateLayout& walls) {
  if (!partner.empty() || !wall.empty())
    throw std::logic_error("VerletList::set_layouts after the list was built");
  pair_layout = pairs;
  wall_layout = walls;
}

namespace {

// The history in a file names, per slot, the law that kept it and its count, so that a run whose
// laws changed since (a discharge from another run's fill, say) keeps what its laws share and
// drops the rest.
void put_history(ByteWriter& w, const StateLayout& l, const std::vector<double>& v) {
  w.put(std::uint32_t(l.size));
  for (int s = 0; s < 4; ++s) w.put(l.law[s]), w.put(std::uint32_t(l.count[s]));
  w.put(v);
}

void get_history(ByteReader& r, const StateLayout& l, std::size_t entries,
                 std::vector<double>& out) {
  const std::size_t size = r.get<std::uint32_t>();
  std::string law[4];
  std::uint32_t count[4];
  std::size_t offset[4], at = 0;
  for (int s = 0; s < 4; ++s) {
    r.get(law[s]), r.get(count[s]);
    offset[s] = at, at += count[s];
  }
  std::vector<double> in;
  r.get(in);
  if (at != size || in.size() != entries * size)
    throw std::runtime_error("checkpoint: the contact history does not match its list");
  out.assign(entries * std::size_t(l.size), 0.0);
  for (int s = 0; s < 4; ++s) {
    if (l.count[s] == 0 || law[s] != l.law[s] || int(count[s]) != l.count[s]) continue;
    for (std::size_t e = 0; e < entries; ++e)
      for (int k = 0; k < l.count[s]; ++k)
        out[e * std::size_t(l.size) + std::size_t(l.offset[s] + k)] =
            in[e * size + offset[s] + std::size_t(k)];
  }
}

// Files written before the laws declared their history ("LIST"): per entry the tangential spring
// (linear_history's) and the rolling spring (epsd's), whatever the laws were.
struct LegacyState {
  Vec3 tangential, rolling;
};
struct LegacySaved {
  std::uint64_t a, b;
  LegacyState s;
};

void from_legacy(const std::vector<LegacyState>& in, const StateLayout& l,
                 std::vector<double>& out) {
  out.assign(in.size() * std::size_t(l.size), 0.0);
  const int t = int(Slot::Tangential), ro = int(Slot::Rolling);
  for (std::size_t e = 0; e < in.size(); ++e) {
    double* h = out.data() + e * std::size_t(l.size);
    if (l.count[t] == 3)
      h[l.offset[t]] = in[e].tangential.x, h[l.offset[t] + 1] = in[e].tangential.y,
      h[l.offset[t] + 2] = in[e].tangential.z;
    if (l.count[ro] == 3)
      h[l.offset[ro]] = in[e].rolling.x, h[l.offset[ro] + 1] = in[e].rolling.y,
      h[l.offset[ro] + 2] = in[e].rolling.z;
  }
}

}  // namespace

// A checkpoint never holds the stash (it lives only inside one Simulation call: stash, move the
// particles, renumber, build).
void VerletList::save(ByteWriter& w) const {
  if (stashed_) throw std::logic_error("VerletList::save between stash_history and build");
  // LST3 adds the per-particle allowances; a list with the fixed skin writes LST2 as before.
  w.tag(allow2_.empty() ? "LST2" : "LST3");
  w.put(offset), w.put(partner);
  put_history(w, pair_layout, hist);
  w.put(wall_offset), w.put(wall);
  put_history(w, wall_layout, wall_hist);
  w.put(builds), w.put(skin), w.put(x_at_build_);
  if (!allow2_.empty()) w.put(allow2_);
}

void VerletList::load(ByteReader& r) {
  allow2_.clear();
  if (r.next_is("LIST")) {
    std::vector<LegacyState> pairs_in, walls_in;
    r.tag("LIST");
    r.get(offset), r.get(partner), r.get(pairs_in), r.get(wall_offset), r.get(wall),
        r.get(walls_in);
    if (pairs_in.size() != partner.size() || walls_in.size() != wall.size())
      throw std::runtime_error("checkpoint: the contact history does not match its list");
    from_legacy(pairs_in, pair_layout, hist);
    from_legacy(walls_in, wall_layout, wall_hist);
    r.get(builds), r.get(skin), r.get(x_at_build_);
    const bool stashed = r.get<std::uint8_t>() != 0;
    std::vector<LegacySaved> pairs, walls;
    r.get(pairs), r.get(walls);
    if (stashed || !pairs.empty() || !walls.empty())
      throw std::runtime_error("checkpoint: the neighbour list holds a stashed contact history");
  } else {
    const bool own = r.next_is("LST3");
    r.tag(own ? "LST3" : "LST2");
    r.get(offset), r.get(partner);
    get_history(r, pair_layout, partner.size(), hist);
    r.get(wall_offset), r.get(wall);
    get_history(r, wall_layout, wall.size(), wall_hist);
    r.get(builds), r.get(skin), r.get(x_at_build_);
    if (own) {
      r.get(allow2_);
      if (allow2_.size() != x_at_build_.size())
        throw std::runtime_error("checkpoint: the skin allowances do not match the particles");
    }
  }
  allow2_all_ = 0.25 * skin * skin;
  // A NaN or out-of-range allowance would stop the list from ever being rebuilt (missed contacts).
  for (const double a2 : allow2_)
    if (!(a2 > 0.0 && a2 <= allow2_all_))
      throw std::runtime_error(
          "checkpoint: a skin allowance is outside (0, skin/2] (damaged file)");
  stashed_ = false;
  check_ids_ = false;  // the ids are not in the list's part of the file: trust the checkpoint
}

}  // namespace silodem
