// SPDX-License-Identifier: MIT
// Throughput of one full time step, Simulation::step() (neighbour check and rebuild when due,
// contact forces, velocity-Verlet integration), on a settled dense random bed of cohesive
// coarse-grained coal (k = 3), for 1 and 2 OpenMP threads. The figure of merit is particle-steps
// per second (issue 6); BENCHMARKS.md at the repository root holds the numbers.
//
// The bed is made once per particle count and process: the paper's two coals at k = 3
// (8.4 mm / 1567 kg/m^3 and 9.6 mm / 1268 kg/m^3, mixed at random) on a jittered face-centred
// lattice in a box of six plane walls, settled under gravity until the kinetic energy per particle
// is small. Every (particles, threads) case then runs its own Simulation started from that state
// with dt = t_col / 50 and skin = 0.25 d_min, as a case file would give.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/constants.hpp"
#include "core/random.hpp"
#include "engine/simulation.hpp"
#include "engine/walls/plane.hpp"
#include "model/coarse_graining.hpp"
#include "model/contact/contact_model.hpp"
#include "model/material.hpp"

namespace {

using silodem::ContactModel;
using silodem::ContactSpec;
using silodem::Simulation;
using silodem::SimulationSettings;
using silodem::Slot;
using silodem::SlotChoice;
using silodem::Vec3;

// ---- the two coals at k = 3 ----------------------------------------------------------------
struct Coal {
  double diameter;     // m, coarse-grained (3 x the measured mean size)
  double density;      // kg/m^3, true density
  double cohesion_cg;  // N, F_L,cg at k = 3
};
const Coal kCoals[] = {
    {8.4e-3, 1567.0, 0.26},   // Longwanggou
    {9.6e-3, 1268.0, 0.417},  // Indonesian
};
constexpr int kNumCoals = 2;

constexpr double kStepsPerCollision = 50.0;  // dt = t_col,min / 50 (MFIX default)
constexpr double kSkinOverDmin = 0.25;

// ---- contact model, built without a case file --------------------------------------------
// One slot's values, checked against the fields the law declares so that a renamed or added key
// in src/ fails here loudly instead of at ParamValues::number() deep inside configure().
SlotChoice slot(Slot s, const std::string& law, bool wall, const std::string& section,
                const std::map<std::string, double>& numbers,
                const std::map<std::string, std::string>& strings = {}) {
  const silodem::LawEntry* entry = silodem::find_law(s, law);
  if (!entry)
    throw std::runtime_error("bench_step: no " + std::string(slot_name(s)) + " law '" + law + "'");
  SlotChoice c;
  c.law = law;
  c.values.section = section;
  c.values.numbers = numbers;
  c.values.strings = strings;
  for (const auto& kv : numbers) c.values.given[kv.first] = true;
  for (const auto& kv : strings) c.values.given[kv.first] = true;
  const std::vector<silodem::Field> fields = entry->fields(wall);
  for (const silodem::Field& f : fields)
    if (!c.values.has(f.key))
      throw std::runtime_error("bench_step: " + section + "." + f.key + " is not set");
  for (const auto& kv : c.values.given) {
    const bool declared = std::any_of(fields.begin(), fields.end(),
                                      [&](const silodem::Field& f) { return f.key == kv.first; });
    if (!declared)
      throw std::runtime_error("bench_step: " + section + "." + kv.first + " is unknown");
  }
  return c;
}

ContactSpec contact_spec(bool wall) {
  const std::string base = wall ? "contact.particle_wall." : "contact.particle_particle.";
  // Walls: the friction values of cases/default.toml; particles: the paper's.
  const double friction = wall ? 0.1 : 0.09;
  const double rolling = wall ? 0.5 : 0.6;
  ContactSpec s;
  s.normal = slot(Slot::Normal, "linear_spring_dashpot", wall, base + "normal",
                  {{"stiffness", 1.0e5}, {"restitution", 0.1}, {"clip_attractive", 0.0}});
  s.tangential = slot(Slot::Tangential, "linear_history", wall, base + "tangential",
                      {{"stiffness_ratio", 2.0 / 7.0},
                       {"damping_ratio", 0.5},
                       {"friction", friction},
                       {"cap_sees_cohesion", 0.0}});
  s.rolling = slot(Slot::Rolling, "mfix", wall, base + "rolling", {{"friction", rolling}});
  if (wall)
    s.cohesion =
        slot(Slot::Cohesion, "overlap-only", wall, base + "cohesion", {{"wall_factor", 1.0}});
  else
    s.cohesion =
        slot(Slot::Cohesion, "overlap-only", wall, base + "cohesion", {}, {{"pair_rule", "mean"}});
  return s;
}

ContactModel make_model() {
  silodem::CoarseGraining cg;
  cg.k = 3.0;
  std::vector<double> cohesion;
  for (const Coal& c : kCoals) cohesion.push_back(c.cohesion_cg);
  std::vector<std::string> warnings;
  ContactModel m =
      ContactModel::build(contact_spec(false), contact_spec(true), cohesion, cg, &warnings);
  for (const auto& w : warnings) std::fprintf(stderr, "bench_step: model warning: %s\n", w.c_str());
  return m;
}

double coal_mass(int a) {
  return silodem::sphere_mass(kCoals[a].diameter, kCoals[a].density);
}

double smallest_diameter() {
  double d = kCoals[0].diameter;
  for (const Coal& c : kCoals) d = std::min(d, c.diameter);
  return d;
}
double largest_diameter() {
  double d = kCoals[0].diameter;
  for (const Coal& c : kCoals) d = std::max(d, c.diameter);
  return d;
}

// Shortest pair collision time, each coal at its (only) particle mass.
double shortest_collision_time(const ContactModel& m) {
  double t = 1e300;
  for (int a = 0; a < kNumCoals; ++a)
    for (int b = 0; b < kNumCoals; ++b)
      t = std::min(t, m.pair_collision_time(a, b, coal_mass(a), coal_mass(b)));
  return t;
}

// ---- the bed -------------------------------------------------------------------------------
struct Bed {
  Vec3 box;  // inner size of the box, one corner at the origin (m)
  std::vector<Vec3> x, v, omega;
  std::vector<int> coal;
};

int threads_available() {
#ifdef _OPENMP
  return omp_get_num_procs();
#else
  return 1;
#endif
}

void use_threads(int n) {
#ifdef _OPENMP
  // SimulationSettings::threads reaches the integrator and the force loop only; the neighbour
  // list (verlet_list.cpp) runs with the OpenMP default, so set that too for a fair 1-thread run.
  omp_set_num_threads(n);
#else
  (void)n;
#endif
}

std::unique_ptr<Simulation> make_simulation(const ContactModel& model, double dt, int threads,
                                            const Vec3& box) {
  SimulationSettings s;
  s.dt = dt;
  s.gravity = {0.0, 0.0, -silodem::kGravity};
  s.skin = kSkinOverDmin * smallest_diameter();
  s.threads = threads;
  auto sim = std::make_unique<Simulation>(model, s);
  const Vec3 lo{0.0, 0.0, 0.0};
  sim->add_wall(std::make_unique<silodem::PlaneWall>(lo, Vec3{1, 0, 0}));
  sim->add_wall(std::make_unique<silodem::PlaneWall>(box, Vec3{-1, 0, 0}));
  sim->add_wall(std::make_unique<silodem::PlaneWall>(lo, Vec3{0, 1, 0}));
  sim->add_wall(std::make_unique<silodem::PlaneWall>(box, Vec3{0, -1, 0}));
  sim->add_wall(std::make_unique<silodem::PlaneWall>(lo, Vec3{0, 0, 1}));
  sim->add_wall(std::make_unique<silodem::PlaneWall>(box, Vec3{0, 0, -1}));
  return sim;
}

void add_particles(Simulation& sim, const Bed& bed) {
  auto& p = sim.particles();
  for (std::size_t i = 0; i < bed.x.size(); ++i) {
    const Coal& c = kCoals[bed.coal[i]];
    p.add(bed.x[i], bed.v[i], bed.omega[i], 0.5 * c.diameter, coal_mass(bed.coal[i]), bed.coal[i]);
  }
}

// Mean kinetic energy per particle (J): translation, rotation.
std::pair<double, double> kinetic_energy_per_particle(const Simulation& sim) {
  const auto& p = sim.particles();
  double et = 0.0, er = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    et += 0.5 * p.mass[i] * norm2(p.v[i]);
    er += 0.5 * p.inertia(i) * norm2(p.omega[i]);
  }
  const double n = p.size() > 0 ? double(p.size()) : 1.0;
  return {et / n, er / n};
}

// Pairs in the neighbour list and touching particle-particle pairs, each per particle.
std::pair<double, double> pairs_and_contacts_per_particle(const Simulation& sim) {
  const auto& p = sim.particles();
  const auto& nl = sim.neighbors();
  const std::size_t n = p.size();
  if (n == 0 || nl.offset.size() != n + 1) return {0.0, 0.0};
  long touching = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int e = nl.offset[i]; e < nl.offset[i + 1]; ++e) {
      const auto j = static_cast<std::size_t>(nl.partner[e]);
      const double sum_r = p.radius[i] + p.radius[j];
      if (norm2(p.x[i] - p.x[j]) < sum_r * sum_r) ++touching;
    }
  return {double(nl.partner.size()) / double(n), double(touching) / double(n)};
}

// Face-centred lattice with horizontal (100) planes: square layers of spacing a, every other
// layer shifted by (a/2, a/2). The sites get a random coal and a horizontal jitter that keeps
// neighbours in a layer apart (a > d_max); then, layer by layer from the floor up, each particle is
// lowered until it rests on the highest of the particles below it (the four of the layer under
// it and the one two layers down) with a gap of 1e-3 d_min. The bed starts dense (packing
// fraction about 0.6), no two particles overlap, and settling only has to let each particle
// roll into its pocket.
Bed lattice_bed(std::size_t n) {
  constexpr double kGap = 0.05;    // a = (1 + gap) d_max
  constexpr double kAspect = 1.3;  // bed height / box width
  const double d_max = largest_diameter();
  const double clearance = 1e-3 * smallest_diameter();
  const double a = (1.0 + kGap) * d_max;
  const double jitter = 0.99 * (a - d_max) / (2.0 * std::sqrt(2.0));
  // Layers rest about a / sqrt(2) apart at most; size the box from that (it is an upper bound).
  const int side = std::max(2, static_cast<int>(std::cbrt(double(n) / (kAspect * std::sqrt(2.0)))));
  const auto per_row = static_cast<std::size_t>(side);
  const std::size_t per_layer = per_row * per_row;

  Bed bed;
  const double width = (side + 0.5) * a;
  silodem::Random rng(20240601u + n);
  double z_top = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t iz = k / per_layer, in_layer = k % per_layer;
    const int iy = static_cast<int>(in_layer / per_row), ix = static_cast<int>(in_layer % per_row);
    const double shift = iz % 2 == 1 ? 0.5 * a : 0.0;
    const int coal = rng.uniform() < 0.5 ? 0 : 1;
    const double r = 0.5 * kCoals[coal].diameter;
    Vec3 x{(ix + 0.5) * a + shift + rng.uniform(-jitter, jitter),
           (iy + 0.5) * a + shift + rng.uniform(-jitter, jitter), r + clearance};
    // Supporters: in the layer below, the sites half a spacing away diagonally (in index terms
    // ix - 1 .. ix or ix .. ix + 1, depending on which layer is shifted); two layers down, the
    // same site.
    auto rest_on = [&](std::size_t j) {
      const double sum_r = r + 0.5 * kCoals[bed.coal[j]].diameter;
      const double dx = x.x - bed.x[j].x, dy = x.y - bed.x[j].y;
      const double d2 = dx * dx + dy * dy;
      if (d2 < sum_r * sum_r)
        x.z = std::max(x.z, bed.x[j].z + std::sqrt(sum_r * sum_r - d2) + clearance);
    };
    if (iz >= 1) {
      const int lo = iz % 2 == 1 ? 0 : -1;  // shifted layer: ix, ix + 1; else ix - 1, ix
      for (int oy = lo; oy <= lo + 1; ++oy)
        for (int ox = lo; ox <= lo + 1; ++ox) {
          const int jx = ix + ox, jy = iy + oy;
          if (jx < 0 || jy < 0 || jx >= side || jy >= side) continue;
          rest_on((iz - 1) * per_layer + static_cast<std::size_t>(jy) * per_row +
                  static_cast<std::size_t>(jx));
        }
    }
    if (iz >= 2) rest_on(k - 2 * per_layer);
    z_top = std::max(z_top, x.z);
    bed.x.push_back(x);
    bed.v.push_back({});
    bed.omega.push_back({});
    bed.coal.push_back(coal);
  }
  bed.box = {width, width, z_top + 2.0 * d_max};
  return bed;
}

// Copies the particle state of a Simulation into a bed.
void save_state(const Simulation& sim, Bed& bed) {
  const auto& p = sim.particles();
  bed.x = p.x;
  bed.v = p.v;
  bed.omega = p.omega;
  bed.coal = p.material;
}

// Settles the lattice under gravity in stages, each a fresh Simulation on one thread started from
// the previous state: the bed collapses into its pockets at 10 g, comes to rest at 1 g with an
// extra viscous damping of the particle velocities, and finally runs free at 1 g with the
// benchmark's dt. A stage ends when the translational kinetic energy per particle is below its
// tolerance (a fraction of m_min g d_min) or after a bounded number of steps.
Bed settle(std::size_t n, const ContactModel& model) {
  struct Stage {
    const char* name;
    double steps_per_collision;  // dt = t_col / this
    double g_factor;             // gravity in g
    double damping_time;         // s, extra viscous damping of v and omega; 0 = none
    long min_steps, max_steps;
    double tolerance;  // KE_t per particle / (m_min g d_min)
  };
  const Stage stages[] = {{"collapse at 10 g", 20.0, 10.0, 0.0, 500, 4000, 1e-1},
                          {"damped rest at 1 g", 20.0, 1.0, 1e-3, 100, 1000, 1e-3},
                          {"free rest at 1 g", kStepsPerCollision, 1.0, 0.0, 200, 2000, 1e-3}};
  constexpr long kCheckEvery = 50;
  const bool trace = std::getenv("BENCH_STEP_TRACE") != nullptr;

  const auto t0 = std::chrono::steady_clock::now();
  Bed bed = lattice_bed(n);
  const double t_col = shortest_collision_time(model);
  const double m_min = std::min(coal_mass(0), coal_mass(1));
  const double ke_ref = m_min * silodem::kGravity * smallest_diameter();
  // One thread: settling is a fixture, and it must not depend on a busy second core.
  const int threads = 1;
  use_threads(threads);

  std::pair<double, double> ke;
  std::pair<double, double> contacts;
  bool settled = false;
  long total_steps = 0;
  for (const Stage& st : stages) {
    const double dt = t_col / st.steps_per_collision;
    auto sim = make_simulation(model, dt, threads, bed.box);
    add_particles(*sim, bed);
    sim->set_gravity({0.0, 0.0, -st.g_factor * silodem::kGravity});
    if (st.damping_time > 0.0) {
      const double keep = 1.0 - dt / st.damping_time;
      sim->add_hook({"settling damping", silodem::Phase::StepEnd, 1, [keep](Simulation& s) {
                       auto& p = s.particles();
                       for (std::size_t i = 0; i < p.size(); ++i) {
                         p.v[i] *= keep;
                         p.omega[i] *= keep;
                       }
                     }});
    }
    if (total_steps == 0) {
      sim->initialize();
      const auto pc0 = pairs_and_contacts_per_particle(*sim);
      if (pc0.second > 0.0)
        std::fprintf(stderr, "bench_step: warning: the lattice has %.0f overlapping pairs\n",
                     pc0.second * double(n));
    }
    long steps = 0;
    settled = false;
    while (steps < st.max_steps) {
      sim->run_steps(kCheckEvery);
      steps += kCheckEvery;
      ke = kinetic_energy_per_particle(*sim);
      if (trace) {
        double z_top = 0.0;
        for (const Vec3& x : sim->particles().x) z_top = std::max(z_top, x.z);
        const auto pc = pairs_and_contacts_per_particle(*sim);
        std::fprintf(stderr,
                     "  %s, step %5ld: KE_t %.3g KE_r %.3g (m g d), contacts %.2f, top %.4f m\n",
                     st.name, steps, ke.first / ke_ref, ke.second / ke_ref, 2.0 * pc.second, z_top);
      }
      if (steps >= st.min_steps && ke.first < st.tolerance * ke_ref) {
        settled = true;
        break;
      }
    }
    total_steps += steps;
    std::fprintf(stderr,
                 "bench_step: %zu particles, %s: %ld steps at dt = t_col/%g, KE_t/particle = %.3g "
                 "m_min g d_min%s\n",
                 n, st.name, steps, st.steps_per_collision, ke.first / ke_ref,
                 settled ? "" : " (step limit reached)");
    contacts = pairs_and_contacts_per_particle(*sim);
    save_state(*sim, bed);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double z_top = 0.0;
  for (const Vec3& x : bed.x) z_top = std::max(z_top, x.z);
  std::fprintf(stderr,
               "bench_step: settled %zu particles in %.1f s (%ld steps, %d thread): %.2f contacts "
               "and %.2f list pairs per particle, top centre at z = %.3f m, KE_t/particle = %.3g "
               "m_min g d_min%s\n",
               n, seconds, total_steps, threads, 2.0 * contacts.second, contacts.first, z_top,
               ke.first / ke_ref, settled ? "" : " (NOT below tolerance)");
  return bed;
}

const ContactModel& model() {
  static const ContactModel m = make_model();
  return m;
}

const Bed& settled_bed(std::size_t n) {
  static std::map<std::size_t, Bed> beds;
  auto it = beds.find(n);
  if (it == beds.end()) it = beds.emplace(n, settle(n, model())).first;
  return it->second;
}

// One Simulation per (particles, threads), kept across Google Benchmark's repeated calls.
Simulation& bench_simulation(std::size_t n, int threads) {
  static std::map<std::pair<std::size_t, int>, std::unique_ptr<Simulation>> sims;
  auto& sim = sims[{n, threads}];
  if (!sim) {
    const Bed& bed = settled_bed(n);
    const double dt = shortest_collision_time(model()) / kStepsPerCollision;
    sim = make_simulation(model(), dt, threads, bed.box);
    add_particles(*sim, bed);
    use_threads(threads);
    sim->run_steps(20);  // builds the list, restarts the contact springs, warms the caches
  }
  return *sim;
}

void report(benchmark::State& state, const Simulation& sim, long builds_before) {
  const double n = double(sim.particles().size());
  const auto pc = pairs_and_contacts_per_particle(sim);
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["list_rebuilds"] = double(sim.neighbors().builds - builds_before);
  state.counters["contacts_per_particle"] = 2.0 * pc.second;
  state.counters["pairs_per_particle"] = pc.first;
}

// One ordinary step: the neighbour list is rebuilt only when some particle has moved skin/2.
void BM_Step(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  if (threads > threads_available()) {
    state.SkipWithError("more threads than processors");
    return;
  }
  Simulation& sim = bench_simulation(n, threads);
  use_threads(threads);
  const long builds = sim.neighbors().builds;
  for (auto _ : state) sim.step();
  report(state, sim, builds);
}

// The same step with a neighbour-list rebuild forced every time: what the neighbour update costs
// at most (a settled bed rarely needs one).
void BM_StepRebuild(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  if (threads > threads_available()) {
    state.SkipWithError("more threads than processors");
    return;
  }
  Simulation& sim = bench_simulation(n, threads);
  use_threads(threads);
  const long builds = sim.neighbors().builds;
  for (auto _ : state) {
    sim.request_rebuild();
    sim.step();
  }
  report(state, sim, builds);
}

BENCHMARK(BM_Step)
    ->ArgNames({"particles", "omp_threads"})
    ->ArgsProduct({{50000, 10000}, {1, 2}})
    ->UseRealTime()
    ->MinTime(3.0)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(BM_StepRebuild)
    ->ArgNames({"particles", "omp_threads"})
    ->ArgsProduct({{50000}, {1, 2}})
    ->UseRealTime()
    ->MinTime(1.0)
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const double t_col = shortest_collision_time(model());
  benchmark::AddCustomContext("bed",
                              "two coals at k = 3 (8.4 mm / 1567 kg/m^3, 9.6 mm / 1268 kg/m^3), "
                              "overlap-only cohesion 0.26 / 0.417 N");
  benchmark::AddCustomContext("dt", std::to_string(t_col / kStepsPerCollision) + " s (t_col/50)");
  benchmark::AddCustomContext("skin", std::to_string(kSkinOverDmin * smallest_diameter()) + " m");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
