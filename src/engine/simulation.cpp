// SPDX-License-Identifier: MIT
#include "engine/simulation.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "engine/pair_batch.hpp"
#include "model/contact/dispatch.hpp"

namespace silodem {
namespace {

int thread_count(int requested) {
#ifdef _OPENMP
  return requested > 0 ? requested : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

SILODEM_HOT BodyState body(const ParticleStore& p, std::size_t i) {
  // The inertia the integrator uses (infinite for a particle whose rotation is switched off); a
  // law that does not read it never pays for the division (dispatch.hpp).
  return {p.x[i],          p.v[i], p.omega[i], p.radius[i], p.mass[i], 1.0 / p.inv_inertia[i],
          p.inv_inertia[i]};
}

}  // namespace

Simulation::Simulation(ContactModel model, SimulationSettings settings)
    : model_(std::move(model)), s_(settings) {
  s_.threads = thread_count(s_.threads);
#ifdef _OPENMP
  omp_set_dynamic(0);  // exactly s_.threads threads: the force summation order depends on it
#endif
  list_.threads = s_.threads;
  bool springs = false;
  for (int a = 0; a < model_.materials(); ++a) {
    springs = springs || model_.wall(a).rolling_spring;
    for (int b = 0; b < model_.materials(); ++b)
      springs = springs || model_.pair(a, b).rolling_spring;
  }
  list_.rolling_springs = springs;
}

void Simulation::add_wall(std::unique_ptr<Wall> w) {
  walls_.push_back(std::move(w));
  rebuild_pending_ = true;
}

void Simulation::set_wall_enabled(std::size_t index, bool on) {
  walls_.at(index)->enabled = on;
  rebuild_pending_ = true;
}

void Simulation::initialize() {
  update_neighbors(list_.needs_rebuild(p_));
  compute_forces(/*finish_step=*/false);
  initialized_ = true;
}

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

void Simulation::run_hooks(Phase ph) {
  for (auto& h : hooks_)
    if (h.phase == ph && steps_ % h.every == 0) h.run(*this);
}

void Simulation::step() {
  if (!initialized_) initialize();
  run_hooks(Phase::StepBegin);
  const double dt = s_.dt, half = 0.5 * dt;
  const std::size_t n = p_.size();
  // Velocity Verlet. The dashpots need the velocity at the end of the step, which VV only knows
  // after the forces: they see the predictor v_half + a_old dt/2 (error O(dt^2)) instead of the
  // half-step velocity (error O(dt), 13% in the restitution at e = 0.1 and dt = t_col/50).
  // The half-step velocity is not stored: the force reduction recovers it as the predictor
  // minus the same a_old dt/2 (compute_forces), and finishes the step there. That saves two
  // arrays and two passes over memory; the recovered v_half differs from a stored one by the
  // rounding of the predictor (half an ulp of |v_half + a_old dt/2|).
  // The same pass checks whether some particle has moved far enough to need a new list.
  const bool check = list_.built_for(n);
  int moved = check ? 0 : 1;
#pragma omp parallel for schedule(static) reduction(| : moved) num_threads(s_.threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 dv = p_.f[i] * (half * p_.inv_mass[i]);
    const Vec3 dw = p_.t[i] * (half * p_.inv_inertia[i]);
    const Vec3 v_half = p_.v[i] + dv;
    const Vec3 x = p_.x[i] + v_half * dt;
    p_.x[i] = x;
    p_.v[i] = v_half + dv;
    const Vec3 w_half = p_.omega[i] + dw;
    p_.omega[i] = w_half + dw;
    if (check) moved |= list_.moved_far(i, x) ? 1 : 0;
  }
  update_neighbors(moved != 0);
  compute_forces(/*finish_step=*/true);
  time_ += dt;
  ++steps_;
  if (steps_ % 256 == 0 || steps_ == 1) check_state();
  run_hooks(Phase::StepEnd);
}

void Simulation::run_steps(long n) {
  for (long k = 0; k < n; ++k) step();
}

void Simulation::run_until(double t_end) {
  while (time_ + 0.5 * s_.dt < t_end) step();
}

// Every coal pair uses the same laws (one [contact.particle_particle] section; only parameters
// differ), so the kernels chosen for pair (0, 0) serve all pairs; likewise for the walls.
// The pairs in range go through lane arrays, kLanes at a time (engine/pair_batch.hpp): the same
// kernels and the same order of the sums as one contact at a time, vectorised.
template <class K>
void Simulation::pair_forces(int tid, double guard) {
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
      if (w.sets[k].count > 0) evaluate_lanes<K>(w.params[k], w.sets[k], dt);
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
      list_.set_state(std::size_t(en.e), b.state(l));
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
  constexpr std::size_t PF = 16;
#pragma omp for schedule(static)
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
    // of the coal pairs, so it needs neither j's coal nor its law. ContactModel::build gives
    // every pair the same reach (one cohesion section, one range), so that is each pair's own;
    // were they to differ, a pair beyond its own reach would still come out right: evaluate()
    // gives it zero force and a cleared history, as the miss list does.
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
      const int in = norm2(xi - p_.x[uj]) >= reach * reach ? 0 : 1;  // NaN counts as in range
      w.hits[std::size_t(n_hit)] = e;
      w.misses[std::size_t(n_miss)] = e;
      n_hit += in;
      n_miss += 1 - in;
    }
    for (int k = 0; k < n_miss; ++k) list_.set_state(std::size_t(w.misses[std::size_t(k)]), {});
    for (int k = 0; k < n_hit; ++k) {
      const int e = w.hits[std::size_t(k)];
      const int j = list_.partner[e];
      const std::size_t uj = std::size_t(j);
      const double rj = p_.radius[uj];
      const int set = mi * nm + p_.material[uj];
      LaneSet& ls = w.sets[std::size_t(set)];
      const int lane = ls.add(xi - p_.x[uj], vi, wi, ri, m_i, inv_ii, p_.v[uj], p_.omega[uj], rj,
                              p_.mass[uj], p_.inv_inertia[uj], list_.state(std::size_t(e)));
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
}

// Walls: each particle belongs to one thread, which writes into its own buffers too.
template <class K>
void Simulation::wall_forces(int tid, double guard) {
  const std::size_t n = p_.size();
  const double dt = s_.dt;
  auto& fb = f_buf_[std::size_t(tid)];
  auto& tb = t_buf_[std::size_t(tid)];
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (list_.wall_offset[i] == list_.wall_offset[i + 1]) continue;
    const ContactLaw& law = model_.wall(p_.material[i]);
    const double reach = p_.radius[i] * (1.0 + 2.0 * law.cp.reach_over_d);
    const BodyState bi = body(p_, i);
    for (int e = list_.wall_offset[i]; e < list_.wall_offset[i + 1]; ++e) {
      const Wall& w = *walls_[list_.wall[e]];
      WallHit hit;
      if (!w.near(p_.x[i], reach, hit)) {
        list_.set_wall_state(std::size_t(e), ContactState{});
        continue;
      }
      ContactState st = list_.wall_state(std::size_t(e));
      const ContactGeometry g = wall_geometry(bi, hit.n, hit.distance, w.velocity());
      if (g.overlap > guard * p_.radius[i] && flags_[tid].i < 0)
        flags_[tid] = {long(i), -1 - long(list_.wall[e]), g.overlap};
      const ContactResult r = evaluate<K>(law, g, st, dt);
      list_.set_wall_state(std::size_t(e), st);
      fb[i] += r.force_i;
      tb[i] += r.torque_i;
    }
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
  flags_.assign(std::size_t(nt), OverlapFlag{});
  if (windows_.size() != std::size_t(nt)) {
    const int nm = model_.materials();
    windows_.assign(std::size_t(nt), PairWindow{});
    for (auto& w : windows_) {
      w.sets.resize(std::size_t(nm * nm));
      for (int a = 0; a < nm; ++a)
        for (int b = 0; b < nm; ++b) w.params.push_back(law_params(model_.pair(a, b)));
      for (const auto& lp : w.params) w.reach = std::max(w.reach, 1.0 + lp.cp.reach_over_d);
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
    with_kernels(model_.pair(0, 0), [&](auto k) { pair_forces<decltype(k)>(tid, guard); });
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
  for (const auto& fl : flags_)
    if (fl.i >= 0) overlap_stop(std::size_t(fl.i), fl.j, fl.overlap);
}

std::string Simulation::likely_cause(std::size_t i) const {
  const int m = p_.material[i];
  const double t_col = std::min(model_.pair_collision_time(m, m, p_.mass[i], p_.mass[i]),
                                model_.wall_collision_time(m, p_.mass[i]));
  if (s_.dt > t_col / 10.0)
    return fmt::format(
        "the time step dt = {:.3g} s is {:.2g} x this particle's collision time "
        "t_col = {:.3g} s (use dt <= t_col / 10, better t_col / 50)",
        s_.dt, s_.dt / t_col, t_col);
  return fmt::format(
      "a particle placed inside a wall or another particle, or a contact too "
      "soft for the load (dt = {:.3g} s = t_col / {:.0f})",
      s_.dt, t_col / s_.dt);
}

void Simulation::overlap_stop(std::size_t i, long j, double overlap) const {
  const std::string with =
      j >= 0 ? fmt::format("particle {}", p_.id[std::size_t(j)]) : fmt::format("wall {}", -1 - j);
  throw SimulationError(fmt::format(
      "overlap guard at step {} (t = {:.6g} s): particle {} at ({:.4g}, {:.4g}, {:.4g}) m, "
      "velocity ({:.3g}, {:.3g}, {:.3g}) m/s, overlaps {} by {:.3g} m = {:.2f} of its radius "
      "(limit {}); likely cause: {}",
      steps_, time_, p_.id[i], p_.x[i].x, p_.x[i].y, p_.x[i].z, p_.v[i].x, p_.v[i].y, p_.v[i].z,
      with, overlap, overlap / p_.radius[i], s_.max_overlap, likely_cause(i)));
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

ContactTally Simulation::contact_tally() const {
  const std::size_t n = p_.size();
  ContactTally t;
  t.particle_contacts.assign(n, 0);
  t.wall_contacts.assign(n, 0);
  t.cohesion_sum.assign(n, 0.0);
  t.cohesion_max_pp.assign(n, 0.0);
  if (!initialized_) return t;
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState bi = body(p_, i);
    for (int e = list_.offset[i]; e < list_.offset[i + 1]; ++e) {
      const std::size_t j = std::size_t(list_.partner[e]);
      const ContactLaw& law = model_.pair(p_.material[i], p_.material[j]);
      const double reach = (p_.radius[i] + p_.radius[j]) * (1.0 + law.cp.reach_over_d);
      if (norm2(p_.x[i] - p_.x[j]) >= reach * reach) continue;
      ContactState copy = list_.state(std::size_t(e));
      const ContactResult r = evaluate_contact(law, pair_geometry(bi, body(p_, j)), copy, s_.dt);
      if (r.touching) ++t.particle_contacts[i], ++t.particle_contacts[j];
      t.cohesion_sum[i] += r.cohesion;
      t.cohesion_sum[j] += r.cohesion;
      t.cohesion_max_pp[i] = std::max(t.cohesion_max_pp[i], r.cohesion);
      t.cohesion_max_pp[j] = std::max(t.cohesion_max_pp[j], r.cohesion);
    }
    const ContactLaw& wl = model_.wall(p_.material[i]);
    const double reach = p_.radius[i] * (1.0 + 2.0 * wl.cp.reach_over_d);
    for (int e = list_.wall_offset[i]; e < list_.wall_offset[i + 1]; ++e) {
      const Wall& w = *walls_[list_.wall[e]];
      WallHit hit;
      if (!w.enabled || !w.near(p_.x[i], reach, hit)) continue;  // (the list may be stale)
      ContactState copy = list_.wall_state(std::size_t(e));
      const ContactResult r =
          evaluate_contact(wl, wall_geometry(bi, hit.n, hit.distance, w.velocity()), copy, s_.dt);
      if (r.touching) ++t.wall_contacts[i];
      t.cohesion_sum[i] += r.cohesion;
    }
  }
  return t;
}

EnergyBudget Simulation::energy() const {
  EnergyBudget e;
  const double g = norm(s_.gravity);
  const Vec3 up = g > 0 ? -s_.gravity / g : Vec3{0, 0, 1};
  for (std::size_t i = 0; i < p_.size(); ++i) {
    e.translational += 0.5 * p_.mass[i] * norm2(p_.v[i]);
    e.rotational += 0.5 / p_.inv_inertia[i] * norm2(p_.omega[i]);
    e.gravitational += p_.mass[i] * g * dot(p_.x[i], up);
    for (int k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const int j = list_.partner[k];
      const double ov = p_.radius[i] + p_.radius[j] - norm(p_.x[i] - p_.x[j]);
      if (ov > 0)
        e.elastic += 0.5 * model_.pair(p_.material[i], p_.material[j]).np.stiffness * ov * ov;
    }
    for (int k = list_.wall_offset[i]; k < list_.wall_offset[i + 1]; ++k) {
      WallHit hit;
      if (walls_[list_.wall[k]]->near(p_.x[i], p_.radius[i], hit)) {
        const double ov = p_.radius[i] - hit.distance;
        e.elastic += 0.5 * model_.wall(p_.material[i]).np.stiffness * ov * ov;
      }
    }
  }
  return e;
}

void Simulation::check_state() const {
  const double v2max = s_.max_speed > 0 ? s_.max_speed * s_.max_speed : 1e300;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (norm2(p_.v[i]) > v2max && is_finite(p_.v[i]))
      throw SimulationError(fmt::format(
          "speed guard at step {} (t = {:.6g} s): particle {} at ({:.4g}, {:.4g}, {:.4g}) m moves "
          "at {:.3g} m/s, velocity ({:.3g}, {:.3g}, {:.3g}), above the bound {:.3g} m/s; likely "
          "cause: {}",
          steps_, time_, p_.id[i], p_.x[i].x, p_.x[i].y, p_.x[i].z, norm(p_.v[i]), p_.v[i].x,
          p_.v[i].y, p_.v[i].z, s_.max_speed, likely_cause(i)));
    if (!is_finite(p_.x[i]) || !is_finite(p_.v[i]) || !is_finite(p_.omega[i]))
      throw SimulationError(fmt::format(
          "particle {} has a non-finite state at step {} (t = {:.6g} s): position ({}, {}, {}), "
          "velocity ({}, {}, {}); likely cause: time step too large for the stiffness (dt = {:.3g} "
          "s) or particles created overlapping",
          p_.id[i], steps_, time_, p_.x[i].x, p_.x[i].y, p_.x[i].z, p_.v[i].x, p_.v[i].y, p_.v[i].z,
          s_.dt));
  }
}

void Simulation::save(ByteWriter& w) const {
  w.tag("SIMU");
  w.put(time_), w.put(steps_), w.put(std::uint8_t(initialized_)),
      w.put(std::uint8_t(rebuild_pending_));
  w.put(std::uint64_t(walls_.size()));
  for (const auto& wl : walls_) w.put(std::uint8_t(wl->enabled));
  p_.save(w);
  list_.save(w);
}

void Simulation::load(ByteReader& r) {
  r.tag("SIMU");
  r.get(time_), r.get(steps_);
  initialized_ = r.get<std::uint8_t>() != 0;
  rebuild_pending_ = r.get<std::uint8_t>() != 0;
  if (r.get<std::uint64_t>() != walls_.size())
    throw std::runtime_error("checkpoint: the case has a different number of walls");
  for (auto& wl : walls_) wl->enabled = r.get<std::uint8_t>() != 0;
  p_.load(r);
  list_.load(r);
}

}  // namespace silodem
