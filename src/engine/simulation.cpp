// SPDX-License-Identifier: MIT
// Simulation's life cycle and integrator: construction, walls, hooks, velocity Verlet, checkpoint.
// The other units: force_pass.cpp, neighbor_update.cpp, guards.cpp, diagnostics.cpp.
#include "engine/simulation.hpp"

#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

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

}  // namespace

Simulation::Simulation(ContactModel model, SimulationSettings settings)
    : model_(std::move(model)), s_(settings) {
  s_.threads = thread_count(s_.threads);
#ifdef _OPENMP
  omp_set_dynamic(0);  // exactly s_.threads threads: the force summation order depends on it
#endif
  list_.threads = s_.threads;
  list_.skin_floor = s_.skin_floor;
  list_.set_periodic(s_.periodic);
  // One [contact.particle_particle] and one [contact.particle_wall] section: every coal pair has
  // the laws (and so the history layout) of pair (0, 0), every wall contact those of wall 0.
  if (model_.materials() > 0) list_.set_layouts(model_.pair(0, 0).layout, model_.wall(0).layout);
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
  const bool wrap = s_.periodic.any();
  int moved = check ? 0 : 1;
#pragma omp parallel for schedule(static) reduction(| : moved) num_threads(s_.threads) if (n > 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 dv = p_.f[i] * (half * p_.inv_mass[i]);
    const Vec3 dw = p_.t[i] * (half * p_.inv_inertia[i]);
    const Vec3 v_half = p_.v[i] + dv;
    const Vec3 x = wrap ? s_.periodic.wrap(p_.x[i] + v_half * dt) : p_.x[i] + v_half * dt;
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

void Simulation::save(ByteWriter& w) const {
  // SIM2 adds the walls' forces of the last force pass, which a driven plate reads at the next
  // step (engine/plate.hpp); SIMU, without them, is still read.
  w.tag("SIM2");
  w.put(time_), w.put(steps_), w.put(std::uint8_t(initialized_)),
      w.put(std::uint8_t(rebuild_pending_));
  w.put(std::uint64_t(walls_.size()));
  for (const auto& wl : walls_) w.put(std::uint8_t(wl->enabled));
  w.put(wall_force_);
  p_.save(w);
  list_.save(w);
}

void Simulation::load(ByteReader& r) {
  const bool with_wall_forces = r.next_is("SIM2");
  if (with_wall_forces)
    r.tag("SIM2");
  else
    r.tag("SIMU");
  r.get(time_), r.get(steps_);
  initialized_ = r.get<std::uint8_t>() != 0;
  rebuild_pending_ = r.get<std::uint8_t>() != 0;
  if (r.get<std::uint64_t>() != walls_.size())
    throw std::runtime_error("checkpoint: the case has a different number of walls");
  for (auto& wl : walls_) wl->enabled = r.get<std::uint8_t>() != 0;
  if (with_wall_forces) {
    r.get(wall_force_);
    if (!wall_force_.empty() && wall_force_.size() != walls_.size())
      throw std::runtime_error("checkpoint: wall forces of a different number of walls");
  }
  p_.load(r);
  list_.load(r);
}

}  // namespace silodem
