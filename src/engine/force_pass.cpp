// SPDX-License-Identifier: MIT
// The force pass of Simulation: pair contacts through the lanes, wall contacts, and the fixed-order
// reduction of the per-thread buffers that also finishes the velocity-Verlet step.
#include <algorithm>
#include <chrono>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "engine/contact_visit.hpp"
#include "engine/pair_batch.hpp"
#include "engine/simulation.hpp"
#include "model/contact/dispatch.hpp"

namespace silodem {

// Every coal pair uses the same laws (one [contact.particle_particle] section; only parameters
// differ), so the kernels chosen for pair (0, 0) serve all pairs; likewise for the walls.
// The pairs in range go through lane arrays, kLanes at a time (engine/pair_batch.hpp): the same
// kernels and the same order of the sums as one contact at a time, vectorised.
template <class K>
void Simulation::pair_forces(int tid, int team, double guard) {
  const auto t_start = std::chrono::steady_clock::now();
  constexpr int H = HistoryOf<K>::size;  // = list_.layout().size (the same laws)
  const std::size_t n = p_.size();
  const double dt = s_.dt;
  const int nm = model_.materials();
  auto& fb = f_buf_[std::size_t(tid)];
  auto& tb = t_buf_[std::size_t(tid)];
  PairWindow& w = windows_[std::size_t(tid)];
  // Evaluates the pairs in flight, then adds their forces to this thread's buffers and writes
  // their history back, in list order.
  auto flush = [&] {
    for (std::size_t k = 0; k < w.sets.size(); ++k)
      if (w.sets[k].count > 0) evaluate_lanes<K>(*w.laws[k], w.sets[k], dt);
    for (int k = 0; k < w.count; ++k) {
      const PairWindow::Entry& en = w.entries[k];
      LaneSet& b = w.sets[std::size_t(en.set)];
      const int l = en.lane;
      if (b.overlap[l] > guard * std::min(b.ri[l], b.rj[l]) && flags_[tid].i < 0)
        flags_[tid] = {long(en.i), long(en.j), b.overlap[l]};
      const Vec3 f = LaneSet::get(b.f, l);
      fb[std::size_t(en.i)] += f;
      fb[std::size_t(en.j)] -= f;
      tb[std::size_t(en.i)] += LaneSet::get(b.ti, l);
      tb[std::size_t(en.j)] += LaneSet::get(b.tj, l);
      list_.set_state_n<H>(std::size_t(en.e), b.state<H>(l));
    }
    for (auto& set : w.sets) set.count = 0;
    w.count = 0;
  };
  // The buffers are summed in thread order afterwards, so a run is bitwise reproducible for a
  // given thread count. The range of indices this thread writes, [lo, hi), tells the reduction
  // which parts of the buffer to read: a thread's partners j lie mostly near its own i.
  std::size_t lo = n, hi = 0;
  // The data of the partner PF pairs ahead are requested before they are needed: in a bed
  // larger than the caches the loop otherwise waits for them (it pays on the 1e6-particle bed and
  // changes nothing on the silo bed: BENCHMARKS.md, "What the engine does to be fast").
  // Prefetches never fault.
  const std::size_t n_pairs = list_.partner.size();
  const PeriodicBox& box = s_.periodic;
  const bool pbc = box.any();
  constexpr std::size_t PF = 16;
  // nowait: the barrier is below, after this thread's time in the loop is taken.
#pragma omp for schedule(static) nowait
  for (std::size_t i = 0; i < n; ++i) {
    lo = std::min(lo, i);
    hi = std::max(hi, i + 1);
    const int mi = p_.material[i];
    // i's data in locals: the lane arrays are doubles too, so the compiler could not keep them
    // in registers across the stores into the lanes.
    const Vec3 xi = p_.x[i], vi = p_.v[i], wi = p_.omega[i];
    const double ri = p_.radius[i], m_i = p_.mass[i], inv_ii = p_.inv_inertia[i];
    // First which partners are in range, without a branch on it (half the listed pairs in a
    // flowing bed: a coin toss for the branch predictor): the entries are sorted into two
    // lists. Then the history of the pairs out of range is cleared, and only the pairs in
    // range are copied into the lanes (the flush writes their new history back), so the data
    // of j are loaded only for pairs that touch. "In range" is tested with the longest reach
    // of the coal pairs, so it needs neither j's coal nor its law. Every pair has the same reach
    // (one cohesion section) unless a per-coal table changes a range; where they differ, a pair
    // beyond its own reach still comes out right: evaluate() gives it zero force and a cleared
    // history, as the miss list does.
    const int e0 = list_.offset[i], e1 = list_.offset[i + 1];
    if (w.hits.size() < std::size_t(e1 - e0)) {
      w.hits.resize(std::size_t(e1 - e0));
      w.misses.resize(std::size_t(e1 - e0));
    }
    int n_hit = 0, n_miss = 0;
    for (int e = e0; e < e1; ++e) {
      const std::size_t uj = std::size_t(list_.partner[e]);
      if (std::size_t(e) + PF < n_pairs) {
        const std::size_t jp = std::size_t(list_.partner[std::size_t(e) + PF]);
        __builtin_prefetch(&p_.x[jp]);
        __builtin_prefetch(&p_.v[jp]);
        __builtin_prefetch(&p_.omega[jp]);
        __builtin_prefetch(&p_.radius[jp]);
        __builtin_prefetch(&p_.mass[jp]);
        __builtin_prefetch(&p_.inv_inertia[jp]);
        __builtin_prefetch(&p_.material[jp]);
      }
      const double reach = (ri + p_.radius[uj]) * w.reach;
      const Vec3 d = pbc ? box.image(xi - p_.x[uj]) : xi - p_.x[uj];
      const int in = norm2(d) >= reach * reach ? 0 : 1;  // NaN counts as in range
      w.hits[std::size_t(n_hit)] = e;
      w.misses[std::size_t(n_miss)] = e;
      n_hit += in;
      n_miss += 1 - in;
    }
    for (int k = 0; k < n_miss; ++k)
      list_.set_state_n<H>(std::size_t(w.misses[std::size_t(k)]), {});
    for (int k = 0; k < n_hit; ++k) {
      const int e = w.hits[std::size_t(k)];
      const int j = list_.partner[e];
      const std::size_t uj = std::size_t(j);
      const double rj = p_.radius[uj];
      const int set = mi * nm + p_.material[uj];
      LaneSet& ls = w.sets[std::size_t(set)];
      const Vec3 d = pbc ? box.image(xi - p_.x[uj]) : xi - p_.x[uj];
      const int lane = ls.add<H>(d, vi, wi, ri, m_i, inv_ii, p_.v[uj], p_.omega[uj], rj,
                                 p_.mass[uj], p_.inv_inertia[uj], list_.state_n<H>(std::size_t(e)));
      w.entries[w.count++] = {int(i), j, e, set, lane};
      // The flush adds into j's force and torque: requested now, they have arrived by then (a
      // miss there was the largest single stall of the pair loop).
      __builtin_prefetch(&fb[uj], 1);
      __builtin_prefetch(&tb[uj], 1);
      if (w.full()) flush();
      hi = std::max(hi, uj + 1);  // j > i in the half list
    }
  }
  flush();
  // Read after the barriers that end this loop and the wall loop. The wall loop writes only its
  // own i, and two static loops over the same n give each thread the same i (OpenMP 5.0, 2.9.2).
  written_[std::size_t(tid)] = {lo, hi};
  // Only steps on the whole team count: a bed below 512 particles runs on one thread, and its
  // steps would otherwise show as thread 0's imbalance.
  if (team == s_.threads)
    pair_busy_[std::size_t(tid)] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
#pragma omp barrier
}

// Walls: each particle belongs to one thread, which writes into its own buffers too.
template <class K>
void Simulation::wall_forces(int tid, double guard) {
  const std::size_t n = p_.size();
  const double dt = s_.dt;
  auto& fb = f_buf_[std::size_t(tid)];
  auto& tb = t_buf_[std::size_t(tid)];
  auto& wf = wall_f_buf_[std::size_t(tid)];
  std::fill(wf.begin(), wf.end(), Vec3{});
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (list_.wall_offset[i] == list_.wall_offset[i + 1]) continue;
    const ContactLaw& law = model_.wall(p_.material[i]);
    const LawParamsOf<K> lp = typed_params<K>(law);
    const double reach = p_.radius[i] * (1.0 + 2.0 * law.reach_over_d);
    const BodyState bi = body(p_, i);
    for_each_wall_contact(
        list_, walls_, i, p_.x[i], reach,
        [&](std::size_t e, const Wall& w, const WallHit& hit) {
          ContactState st = list_.wall_state(e);
          const ContactGeometry g = wall_geometry(bi, hit.n, hit.distance, w.velocity());
          if (g.overlap > guard * p_.radius[i] && flags_[tid].i < 0)
            flags_[tid] = {long(i), -1 - long(list_.wall[e]), g.overlap};
          const ContactResult r = evaluate<K>(lp, g, st, dt);
          list_.set_wall_state(e, st);
          fb[i] += r.force_i;
          tb[i] += r.torque_i;
          wf[std::size_t(list_.wall[e])] -= r.force_i;
        },
        [&](std::size_t e) { list_.set_wall_state(e, ContactState{}); });
  }
}

void Simulation::compute_forces(bool finish_step) {
  const std::size_t n = p_.size();
  // Small systems run on one thread: a parallel region costs more than it saves there.
  const int nt = n < 512 ? 1 : s_.threads;
  if (int(f_buf_.size()) < nt) {
    f_buf_.resize(std::size_t(nt));
    t_buf_.resize(std::size_t(nt));
  }
  wall_f_buf_.resize(std::size_t(nt));
  for (auto& b : wall_f_buf_) b.resize(walls_.size());
  flags_.assign(std::size_t(nt), OverlapFlag{});
  if (pair_busy_.size() < std::size_t(nt)) pair_busy_.resize(std::size_t(nt), 0.0);
  if (windows_.size() != std::size_t(nt)) {
    const int nm = model_.materials();
    windows_.assign(std::size_t(nt), PairWindow{});
    for (auto& w : windows_) {
      w.sets.resize(std::size_t(nm * nm));
      for (int a = 0; a < nm; ++a)
        for (int b = 0; b < nm; ++b) w.laws.push_back(&model_.pair(a, b));
      for (const ContactLaw* l : w.laws) w.reach = std::max(w.reach, 1.0 + l->reach_over_d);
    }
  }
  written_.assign(std::size_t(nt), {0, 0});
  const double guard = s_.max_overlap > 0 ? s_.max_overlap : 1e300;
  const double half = 0.5 * s_.dt;
  int team = 1;
#pragma omp parallel num_threads(nt)
  {
#ifdef _OPENMP
    const int tid = omp_get_thread_num();
#pragma omp single
    team = omp_get_num_threads();
#else
    const int tid = 0;
#endif
    // The buffers are zeroed by the reduction below as it reads them (one pass over memory
    // instead of two); only a new size needs a fresh fill.
    auto& fb = f_buf_[tid];
    auto& tb = t_buf_[tid];
    if (fb.size() != n) fb.assign(n, Vec3{});
    if (tb.size() != n) tb.assign(n, Vec3{});
    // Pair contacts (half list), then walls; each thread accumulates into its own buffers.
    with_kernels(model_.pair(0, 0), [&](auto k) { pair_forces<decltype(k)>(tid, nt, guard); });
    with_kernels(model_.wall(0), [&](auto k) { wall_forces<decltype(k)>(tid, guard); });
    // Reduce: gravity + external force + the per-thread buffers in fixed order.
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 f = s_.gravity * p_.mass[i] + p_.f_ext[i];
      Vec3 t;
      for (int k = 0; k < team; ++k) {
        if (i < written_[k].first || i >= written_[k].second) continue;  // still zero there
        f += f_buf_[k][i];
        t += t_buf_[k][i];
        f_buf_[k][i] = Vec3{};
        t_buf_[k][i] = Vec3{};
      }
      if (finish_step) {
        // The second half-kick of step(): v = v_half + a_new dt/2, with v_half recovered from
        // the predictor p_.v = v_half + a_old dt/2 (a_old still in p_.f).
        const double hm = half * p_.inv_mass[i], hw = half * p_.inv_inertia[i];
        p_.v[i] = (p_.v[i] - p_.f[i] * hm) + f * hm;
        p_.omega[i] = (p_.omega[i] - p_.t[i] * hw) + t * hw;
      }
      p_.f[i] = f;
      p_.t[i] = t;
    }
  }
  wall_force_.assign(walls_.size(), Vec3{});
  for (int k = 0; k < team; ++k)
    for (std::size_t w = 0; w < walls_.size(); ++w)
      wall_force_[w] += wall_f_buf_[std::size_t(k)][w];
  for (const auto& fl : flags_)
    if (fl.i >= 0) overlap_stop(std::size_t(fl.i), fl.j, fl.overlap);
}

}  // namespace silodem
