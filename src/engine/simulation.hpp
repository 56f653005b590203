// SPDX-License-Identifier: MIT
// Owns the particles, walls, neighbour list with contact history and the contact model, and
// advances them in time with velocity Verlet:
//   hooks(begin) -> v_half = v + F/m dt/2 -> x += v_half dt -> neighbours
//   -> forces (dashpots see the predicted v_half + F_old/m dt/2) -> v = v_half + F/m dt/2 ->
//   hooks(end)
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/hooks.hpp"
#include "engine/neighbor/verlet_list.hpp"
#include "engine/pair_batch.hpp"
#include "engine/particle_store.hpp"
#include "engine/periodic.hpp"
#include "engine/walls/wall.hpp"
#include "model/contact/contact_model.hpp"

namespace silodem {

struct SimulationSettings {
  double dt = 1e-5;               // s
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s^2
  double skin = 1e-3;             // m, Verlet skin
  // Per-particle skin (speed only): the smallest allowance a slow particle gets at a list build,
  // as a fraction of skin / 2; 1 = every particle skin / 2 (VerletList::skin_floor).
  double skin_floor = 1.0;
  int threads = 0;  // 0 = OpenMP default
  // Guards: the run stops with a diagnostic when a particle is faster than max_speed (m/s; 0 =
  // no bound) or a contact overlaps by more than max_overlap times the smaller radius (0 = off).
  double max_speed = 0.0;
  double max_overlap = 0.5;
  // Reorder the particles along a Morton (Z-order) curve before every `reorder_every`-th
  // neighbour-list build (0 = never), so that neighbours sit close in memory.
  int reorder_every = 0;
  // Periodic boundaries (engine/periodic.hpp): positions wrap into the box along its periodic
  // axes and pairs interact through the nearest image.
  PeriodicBox periodic;
};

// What each particle's contacts do right now, for observers (probes, VTK output). Computed on
// demand by a read-only pass over the neighbour list (the history is copied, never advanced).
struct ContactTally {
  std::vector<int> particle_contacts;   // touching particle partners (overlap > 0)
  std::vector<int> wall_contacts;       // touching walls
  std::vector<double> cohesion_sum;     // N, sum of cohesive force magnitudes, particles + walls
  std::vector<double> cohesion_max_pp;  // N, largest cohesive force from one particle partner
};

struct EnergyBudget {
  double translational = 0.0, rotational = 0.0, gravitational = 0.0, elastic = 0.0;
  double total() const { return translational + rotational + gravitational + elastic; }
};

class Simulation {
 public:
  Simulation(ContactModel model, SimulationSettings settings);

  ParticleStore& particles() { return p_; }
  const ParticleStore& particles() const { return p_; }
  const ContactModel& model() const { return model_; }
  const SimulationSettings& settings() const { return s_; }
  void set_reorder_every(int n) { s_.reorder_every = n; }  // speed only (benchmarks)
  void set_gravity(const Vec3& g) { s_.gravity = g; }
  void add_wall(std::unique_ptr<Wall> w);
  const WallList& walls() const { return walls_; }
  // A wall to move (Wall::translate, set_velocity: a driven plate). A wall moved by more than a
  // quarter of the skin since the last list build needs request_rebuild().
  Wall& wall(std::size_t index) { return *walls_.at(index); }
  // The force the particles exert on wall `index` in the last force pass (N; the sum of its
  // contacts' forces, the reaction of what it does to them).
  Vec3 wall_force(std::size_t index) const {
    return index < wall_force_.size() ? wall_force_[index] : Vec3{};
  }
  // Switch a wall on or off (e.g. open a valve); its contacts end with it.
  void set_wall_enabled(std::size_t index, bool on);
  void add_hook(Hook h) { hooks_.push_back(std::move(h)); }

  // Builds the neighbour list and the forces of the initial state. Called by step() if needed.
  void initialize();
  void step();
  void run_steps(long n);
  void run_until(double t_end);  // steps while time() < t_end (within half a step)

  double time() const { return time_; }
  long step_count() const { return steps_; }
  double dt() const { return s_.dt; }

  // Removes particles by index (any order); contact history of the others is kept.
  void remove_particles(std::vector<std::size_t> indices);
  // Forces a neighbour-list rebuild before the next force evaluation (tests, wall changes).
  void request_rebuild() { rebuild_pending_ = true; }
  const VerletList& neighbors() const { return list_; }

  // History of the contact between two particles (by stable id), if they are listed.
  std::optional<ContactState> contact_state(std::uint64_t id_a, std::uint64_t id_b,
                                            bool* flipped) const;
  // Checkpoint of the dynamic state: particles, neighbour list with contact history, walls
  // on/off, time and step counter. The model, settings, walls and hooks come from the case.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

  // Per thread: wall-clock seconds spent in its share of the pair loop (the half list split by
  // particle index) since the last reset, without the wait at the barrier that ends the loop;
  // only force passes on all `threads` threads count (a small bed runs on one).
  // max / mean over the threads is the loop's imbalance (bench's `pair_loop_imbalance`).
  const std::vector<double>& pair_loop_seconds() const { return pair_busy_; }
  void reset_pair_loop_seconds() { pair_busy_.assign(pair_busy_.size(), 0.0); }

  // Per-particle contact counts and cohesive forces of the current state (see ContactTally).
  ContactTally contact_tally() const;
  // Kinetic, rotational, gravitational (relative to z = 0 along -gravity) and spring energy.
  EnergyBudget energy() const;

 private:
  // Forces and torques of the current positions into p_.f / p_.t; with finish_step, also the
  // second half-kick of step() (p_.v / p_.omega hold the predictor until then).
  void compute_forces(bool finish_step);
  // The two halves of compute_forces' parallel region, compiled per law combination
  // (model/contact/dispatch.hpp); orphaned `omp for` loops.
  template <class K>
  void pair_forces(int tid, int team, double guard);  // team: the threads of this pass
  template <class K>
  void wall_forces(int tid, double guard);
  void update_neighbors(bool moved);  // moved: some particle moved over its allowance
  void reorder_spatially();
  void run_hooks(Phase ph);
  void check_state() const;
  // x_i - x_j through the nearest image (the plain difference without periodic boundaries).
  Vec3 separation(std::size_t i, std::size_t j) const {
    const Vec3 d = p_.x[i] - p_.x[j];
    return s_.periodic.any() ? s_.periodic.image(d) : d;
  }
  [[noreturn]] void overlap_stop(std::size_t i, long j, double overlap) const;
  std::string likely_cause(std::size_t i) const;

  ContactModel model_;
  SimulationSettings s_;
  ParticleStore p_;
  WallList walls_;
  VerletList list_;
  std::vector<Hook> hooks_;
  std::vector<std::vector<Vec3>> f_buf_, t_buf_;  // per-thread force/torque buffers
  std::vector<std::vector<Vec3>> wall_f_buf_;     // per thread: force on each wall
  std::vector<Vec3> wall_force_;                  // their sum, in thread order
  // Per thread: the index range its pair loop wrote into its buffers this step.
  std::vector<std::pair<std::size_t, std::size_t>> written_;
  std::vector<PairWindow> windows_;  // per thread: the pairs in flight (engine/pair_batch.hpp)
  struct OverlapFlag {
    long i = -1, j = -1;  // j = -1 - wall index for a wall contact
    double overlap = 0.0;
  };
  std::vector<OverlapFlag> flags_;  // per thread: the first contact over the overlap guard
  std::vector<double> pair_busy_;   // per thread: seconds in the pair loop (pair_loop_seconds)
  double time_ = 0.0;
  long steps_ = 0;
  bool initialized_ = false;
  bool rebuild_pending_ = true;
};

}  // namespace silodem
