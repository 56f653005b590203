// SPDX-License-Identifier: MIT
// Throughput of one full time step, Simulation::step() (neighbour check and rebuild when due,
// contact forces, velocity-Verlet integration), on a settled dense random bed of cohesive
// coarse-grained coal (k = 3), for 1 and 2 OpenMP threads. The figure of merit is particle-steps
// per second (issue 6); BENCHMARKS.md at the repository root holds the numbers ("Scaling").
//
// The bed is made once per particle count and process: the paper's two coals at k = 3
// (8.4 mm / 1567 kg/m^3 and 9.6 mm / 1268 kg/m^3, mixed at random) deposited on a jittered
// face-centred lattice in a box of six plane walls, then settled under gravity until the kinetic
// energy per particle is small (a bounded number of steps, on one thread). Every (particles,
// threads) case then runs its own Simulation started from that state with dt = t_col / 50 and
// skin = 0.25 d_min, as a case file would give. BENCH_STEP_TRACE=1 traces the settling; the
// settled bed is cached on disk (BENCH_STEP_CACHE, below).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
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
constexpr int kNumCoals = static_cast<int>(std::size(kCoals));

constexpr double kStepsPerCollision = 50.0;  // dt = t_col,min / 50 (MFIX default)
constexpr double kSkinOverDmin = 0.25;

// ---- contact model, built without a case file --------------------------------------------
// One slot's values, checked against the fields the law declares: a key the law does not know is
// an error, a declared key left out takes the field's default (as the case loader does) and is
// reported on stderr, and a required one left out is an error. So a field added to or renamed in
// src/ shows up here instead of deep inside configure().
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
  for (const auto& kv : c.values.given) {
    const bool declared = std::any_of(fields.begin(), fields.end(),
                                      [&](const silodem::Field& f) { return f.key == kv.first; });
    if (!declared)
      throw std::runtime_error("bench_step: " + section + "." + kv.first + " is unknown");
  }
  for (const silodem::Field& f : fields) {
    if (c.values.has(f.key)) continue;
    if (f.kind == silodem::FieldKind::String && !f.default_string.empty()) {
      c.values.strings[f.key] = f.default_string;
      std::fprintf(stderr, "bench_step: %s.%s = \"%s\" (default)\n", section.c_str(), f.key.c_str(),
                   f.default_string.c_str());
    } else if (f.kind != silodem::FieldKind::String && f.default_number) {
      c.values.numbers[f.key] = *f.default_number * f.to_si;
      std::fprintf(stderr, "bench_step: %s.%s = %g (default)\n", section.c_str(), f.key.c_str(),
                   *f.default_number * f.to_si);
    } else {
      throw std::runtime_error("bench_step: " + section + "." + f.key + " is not set");
    }
    c.values.given[f.key] = false;
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
  // regularize = 1: the law's default, the sign switch smoothed near omega = 0.
  s.rolling = slot(Slot::Rolling, "mfix", wall, base + "rolling",
                   {{"friction", rolling}, {"regularize", 1.0}});
  // factor = 1: the full F_L,cg of Eq. 13-14 (the paper's).
  if (wall)
    s.cohesion = slot(Slot::Cohesion, "overlap-only", wall, base + "cohesion",
                      {{"wall_factor", 1.0}, {"factor", 1.0}});
  else
    s.cohesion = slot(Slot::Cohesion, "overlap-only", wall, base + "cohesion", {{"factor", 1.0}},
                      {{"pair_rule", "mean"}});
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
      t = std::min(t, m.pair_collision_time(a, b, coal_mass(a), coal_mass(b),
                                            0.5 * kCoals[a].diameter, 0.5 * kCoals[b].diameter));
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

// Pairs in the (half) neighbour list and touching particle-particle pairs, each per particle;
// the coordination number is twice the second.
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

// Centre of a sphere touching three spheres: |p - c[m]| = s[m] (centres c, distances s = sums of
// radii), the solution above the plane of the three. False when there is none.
bool rest_on_three(const Vec3 c[3], const double s[3], Vec3& p) {
  const Vec3 ab = c[1] - c[0], ac = c[2] - c[0];
  const double d = norm(ab);
  if (d == 0.0) return false;
  const Vec3 ex = ab / d;
  const double i = dot(ex, ac);
  const Vec3 ey_raw = ac - i * ex;
  const double j = norm(ey_raw);
  if (j < 1e-9 * d) return false;  // collinear centres
  const Vec3 ey = ey_raw / j;
  Vec3 ez = cross(ex, ey);
  if (ez.z < 0.0) ez = -ez;
  const double x = (s[0] * s[0] - s[1] * s[1] + d * d) / (2.0 * d);
  const double y = (s[0] * s[0] - s[2] * s[2] + i * i + j * j) / (2.0 * j) - (i / j) * x;
  const double z2 = s[0] * s[0] - x * x - y * y;
  if (z2 < 0.0) return false;
  p = c[0] + x * ex + y * ey + std::sqrt(z2) * ez;
  return true;
}

// A deposited bed on a face-centred lattice with horizontal (100) planes: square layers of
// spacing a, every other layer shifted by (a/2, a/2). Each site gets a random coal and a small
// horizontal jitter; then, from the floor up, each particle is put at the lowest position within
// a/2 of its site that rests on three particles placed before it (from the four under the site
// and the neighbours already placed in its own layer) and touches none; failing that, above the
// highest particle under its site. A gap of 1e-5 d_min is left at each support, so nothing
// overlaps and the bed starts almost at rest, at a solid fraction of about 0.5.
Bed lattice_bed(std::size_t n) {
  constexpr double kGap = 0.05;  // a = (1 + gap) d_max
  // Bed height / box width, roughly. The 1e6 bed is made flatter: at 1.3 it would be about 100
  // layers deep, and a particle dropped from its top trips the overlap guard while settling.
  const double kAspect = n > 200000 ? 0.3 : 1.3;
  const double d_max = largest_diameter();
  const double clearance = 1e-5 * smallest_diameter();
  const double a = (1.0 + kGap) * d_max;
  const double jitter = 0.99 * (a - d_max) / (2.0 * std::sqrt(2.0));
  const int side = std::max(2, static_cast<int>(std::cbrt(double(n) / (kAspect * std::sqrt(2.0)))));
  const auto per_row = static_cast<std::size_t>(side);
  const std::size_t per_layer = per_row * per_row;
  const double width = (side + 0.5) * a;

  Bed bed;
  auto radius = [&](std::size_t j) { return 0.5 * kCoals[bed.coal[j]].diameter; };
  auto placed = [&](std::size_t iz, int jx, int jy, std::size_t& j) {
    if (jx < 0 || jy < 0 || jx >= side || jy >= side) return false;
    j = iz * per_layer + static_cast<std::size_t>(jy) * per_row + static_cast<std::size_t>(jx);
    return j < bed.x.size();
  };
  // Calls f(j) for every particle placed so far within two sites of (iz, ix, iy), in this layer
  // and the four below it (a particle placed by the fallback may sit a layer or two high).
  auto for_placed_near = [&](std::size_t iz, int ix, int iy, auto&& f) {
    for (std::size_t dz = 0; dz <= std::min<std::size_t>(iz, 4); ++dz)
      for (int jy = iy - 2; jy <= iy + 2; ++jy)
        for (int jx = ix - 2; jx <= ix + 2; ++jx) {
          std::size_t j = 0;
          if (placed(iz - dz, jx, jy, j)) f(j);
        }
  };

  silodem::Random rng(20240601u + n);
  std::vector<std::size_t> support;
  double z_top = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t iz = k / per_layer, in_layer = k % per_layer;
    const int iy = static_cast<int>(in_layer / per_row), ix = static_cast<int>(in_layer % per_row);
    const double shift = iz % 2 == 1 ? 0.5 * a : 0.0;
    const int coal = rng.uniform() < 0.5 ? 0 : 1;
    const double r = 0.5 * kCoals[coal].diameter;
    const Vec3 site{(ix + 0.5) * a + shift + rng.uniform(-jitter, jitter),
                    (iy + 0.5) * a + shift + rng.uniform(-jitter, jitter), 0.0};

    // Fallback: at the site, just above everything placed near it (or on the floor).
    Vec3 best{site.x, site.y, r + clearance};
    for_placed_near(iz, ix, iy, [&](std::size_t j) {
      const double sum = r + radius(j);
      const double dx = site.x - bed.x[j].x, dy = site.y - bed.x[j].y;
      const double h2 = sum * sum - dx * dx - dy * dy;
      if (h2 > 0.0) best.z = std::max(best.z, bed.x[j].z + std::sqrt(h2) + clearance);
    });
    // Resting on three: the sites under this one and the placed neighbours in this layer.
    support.clear();
    std::size_t j = 0;
    if (iz >= 1) {
      const int lo = iz % 2 == 1 ? 0 : -1;  // shifted layer: ix, ix + 1; else ix - 1, ix
      for (int oy = lo; oy <= lo + 1; ++oy)
        for (int ox = lo; ox <= lo + 1; ++ox)
          if (placed(iz - 1, ix + ox, iy + oy, j)) support.push_back(j);
    }
    for (int oy = -1; oy <= 0; ++oy)
      for (int ox = -1; ox <= 1; ++ox)
        if ((oy < 0 || ox < 0) && placed(iz, ix + ox, iy + oy, j)) support.push_back(j);
    // Within a/2 of the site first; if nothing there is free, within a.
    const Vec3 fallback = best;
    for (double reach : {0.5 * a, a}) {
      for (std::size_t q0 = 0; q0 < support.size(); ++q0)
        for (std::size_t q1 = q0 + 1; q1 < support.size(); ++q1)
          for (std::size_t q2 = q1 + 1; q2 < support.size(); ++q2) {
            const std::size_t t[3] = {support[q0], support[q1], support[q2]};
            const Vec3 c[3] = {bed.x[t[0]], bed.x[t[1]], bed.x[t[2]]};
            const double s[3] = {r + radius(t[0]), r + radius(t[1]), r + radius(t[2])};
            Vec3 p;
            if (!rest_on_three(c, s, p)) continue;
            p.z += clearance;
            const double dx = p.x - site.x, dy = p.y - site.y;
            if (p.z >= best.z || dx * dx + dy * dy > reach * reach) continue;
            if (p.x < r || p.y < r || p.x > width - r || p.y > width - r || p.z < r) continue;
            bool free = true;
            for_placed_near(iz, ix, iy, [&](std::size_t m) {
              const double sum = r + radius(m);
              if (norm2(p - bed.x[m]) < sum * sum) free = false;
            });
            if (free) best = p;
          }
      if (best.z < fallback.z) break;
    }
    z_top = std::max(z_top, best.z);
    bed.x.push_back(best);
    bed.v.push_back({});
    bed.omega.push_back({});
    bed.coal.push_back(coal);
  }
  bed.box = {width, width, z_top + 2.0 * d_max};
  return bed;
}

// Solid fraction of the bed's core: the volume of the spheres whose centres lie at least 2 d_max
// from the side walls and the floor and below 80 % of the bed height, over that region's volume.
double solid_fraction(const Bed& bed) {
  const double margin = 2.0 * largest_diameter();
  double z_top = 0.0;
  for (const Vec3& x : bed.x) z_top = std::max(z_top, x.z);
  const Vec3 lo{margin, margin, margin}, hi{bed.box.x - margin, bed.box.y - margin, 0.8 * z_top};
  if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) return 0.0;
  double solid = 0.0;
  for (std::size_t i = 0; i < bed.x.size(); ++i) {
    const Vec3& x = bed.x[i];
    if (x.x < lo.x || x.y < lo.y || x.z < lo.z || x.x > hi.x || x.y > hi.y || x.z > hi.z) continue;
    const double d = kCoals[bed.coal[i]].diameter;
    solid += silodem::kPi / 6.0 * d * d * d;
  }
  return solid / ((hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z));
}

// Copies the particle state of a Simulation into a bed.
void save_state(const Simulation& sim, Bed& bed) {
  const auto& p = sim.particles();
  bed.x = p.x;
  bed.v = p.v;
  bed.omega = p.omega;
  bed.coal = p.material;
}

// Settles the bed under gravity in stages, each a fresh Simulation on one thread started from the
// previous state: (1) at dt = t_col / 20 until the bed is at rest or for at most 3000 steps,
// (2) the same with an extra viscous damping of v and omega (time constant 1 ms) until it is at
// rest (at most 1000 steps), (3) 100 undamped steps with the benchmark's dt. "At rest" means that
// the translational kinetic energy per particle is below 1e-3 m_min g d_min and the number of
// contacts changed by less than 0.5 % over the last 50 steps. Stage 1 alone would need some 5000
// steps (e = 0.1 damps the last slow rearrangements slowly); stage 2 saves the rest.
Bed settle(std::size_t n, const ContactModel& model) {
  struct Stage {
    const char* name;
    double steps_per_collision;  // dt = t_col / this
    double damping_time;         // s, extra viscous damping of v and omega; 0 = none
    long min_steps, max_steps;
    double tolerance;  // KE_t per particle / (m_min g d_min); 0 = run max_steps
  };
  const Stage stages[] = {{"settling", 20.0, 0.0, 200, 3000, 1e-3},
                          {"damped", 20.0, 1e-3, 100, 1000, 1e-3},
                          {"running on", kStepsPerCollision, 0.0, 100, 100, 0.0}};
  constexpr long kCheckEvery = 50;
  constexpr double kContactChange = 0.005;
  const bool trace = std::getenv("BENCH_STEP_TRACE") != nullptr;

  const auto t0 = std::chrono::steady_clock::now();
  Bed bed = lattice_bed(n);
  const double t_col = shortest_collision_time(model);
  const double m_min = std::min(coal_mass(0), coal_mass(1));
  const double ke_ref = m_min * silodem::kGravity * smallest_diameter();
  // One thread: settling is a fixture, and it must not depend on a busy second core.
  const int threads = 1;
  std::fprintf(stderr, "bench_step: settling %zu particles (one thread)...\n", n);

  std::pair<double, double> ke, contacts;
  bool settled = false;
  long total_steps = 0;
  for (const Stage& st : stages) {
    const double dt = t_col / st.steps_per_collision;
    auto sim = make_simulation(model, dt, threads, bed.box);
    add_particles(*sim, bed);
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
      const double overlapping = pairs_and_contacts_per_particle(*sim).second * double(n);
      if (overlapping > 0.0)
        std::fprintf(stderr, "bench_step: warning: %.0f pairs overlap in the initial bed\n",
                     overlapping);
    }
    const bool bounded = st.tolerance > 0.0;
    bool reached = false;
    long steps = 0;
    double last_contacts = -1.0;
    while (steps < st.max_steps) {
      sim->run_steps(kCheckEvery);
      steps += kCheckEvery;
      ke = kinetic_energy_per_particle(*sim);
      contacts = pairs_and_contacts_per_particle(*sim);
      if (trace) {
        double z_top = 0.0;
        for (const Vec3& x : sim->particles().x) z_top = std::max(z_top, x.z);
        std::fprintf(
            stderr, "  %s, step %5ld: KE_t %.3g KE_r %.3g (m g d), contacts %.3f, top %.4f m\n",
            st.name, steps, ke.first / ke_ref, ke.second / ke_ref, 2.0 * contacts.second, z_top);
      }
      const bool steady =
          std::fabs(contacts.second - last_contacts) <= kContactChange * contacts.second;
      last_contacts = contacts.second;
      if (bounded && steps >= st.min_steps && steady && ke.first < st.tolerance * ke_ref) {
        reached = true;
        break;
      }
    }
    total_steps += steps;
    std::fprintf(stderr,
                 "bench_step: %zu particles, %s: %ld steps at dt = t_col/%g, KE_t/particle = %.3g "
                 "m_min g d_min%s\n",
                 n, st.name, steps, st.steps_per_collision, ke.first / ke_ref,
                 bounded && !reached ? " (step limit reached)" : "");
    if (bounded && &st == &stages[0]) settled = reached;
    save_state(*sim, bed);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(stderr,
               "bench_step: settling %zu particles took %.1f s (%ld steps)%s: %.2f contacts and "
               "%.2f list pairs per particle, solid fraction %.3f\n",
               n, seconds, total_steps, settled ? "" : " (it did not come to rest undamped)",
               2.0 * contacts.second, contacts.first, solid_fraction(bed));
  return bed;
}

const ContactModel& model() {
  static const ContactModel m = make_model();
  return m;
}

// ---- the settled bed, cached on disk --------------------------------------------------------
// Settling the 1e6 bed takes minutes (bench/README.md), longer than timing it, so the state is kept
// in $BENCH_STEP_CACHE (default ~/.cache/silodem; "0" = off) as bench_step-bed-v<V>-<n>.bin and
// reused by later runs, including runs of other commits, which then time the same bed. Bump
// kBedVersion when the lattice, the coals or the settling change.
constexpr int kBedVersion = 1;
constexpr char kBedMagic[8] = {'S', 'D', 'B', 'E', 'D', '0', '0', '1'};

std::string bed_cache_path(std::size_t n) {
  const char* env = std::getenv("BENCH_STEP_CACHE");
  std::string dir;
  if (env && std::string(env) == "0") return {};
  if (env && *env) {
    dir = env;
  } else {
    const char* home = std::getenv("HOME");
    if (!home || !*home) return {};
    dir = std::string(home) + "/.cache/silodem";
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return {};
  return dir + "/bench_step-bed-v" + std::to_string(kBedVersion) + "-" + std::to_string(n) + ".bin";
}

template <class T>
bool put_all(std::FILE* f, const std::vector<T>& v) {
  return std::fwrite(v.data(), sizeof(T), v.size(), f) == v.size();
}
template <class T>
bool get_all(std::FILE* f, std::vector<T>& v, std::size_t n) {
  v.resize(n);
  return std::fread(v.data(), sizeof(T), n, f) == n;
}

bool load_bed(const std::string& path, std::size_t n, Bed& bed) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  char magic[8];
  std::uint64_t count = 0;
  const bool ok = std::fread(magic, 1, 8, f) == 8 && std::equal(magic, magic + 8, kBedMagic) &&
                  std::fread(&count, sizeof count, 1, f) == 1 && count == n &&
                  std::fread(&bed.box, sizeof bed.box, 1, f) == 1 && get_all(f, bed.x, n) &&
                  get_all(f, bed.v, n) && get_all(f, bed.omega, n) && get_all(f, bed.coal, n) &&
                  std::fgetc(f) == EOF;
  std::fclose(f);
  if (!ok) std::fprintf(stderr, "bench_step: ignoring the damaged cache %s\n", path.c_str());
  return ok;
}

void store_bed(const std::string& path, const Bed& bed) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return;
  const std::uint64_t count = bed.x.size();
  bool ok = std::fwrite(kBedMagic, 1, 8, f) == 8 && std::fwrite(&count, sizeof count, 1, f) == 1 &&
            std::fwrite(&bed.box, sizeof bed.box, 1, f) == 1 && put_all(f, bed.x) &&
            put_all(f, bed.v) && put_all(f, bed.omega) && put_all(f, bed.coal);
  ok = std::fclose(f) == 0 && ok;
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, path, ec);
  if (!ok || ec) std::filesystem::remove(tmp, ec);
}

const Bed& settled_bed(std::size_t n) {
  static std::map<std::size_t, Bed> beds;
  auto it = beds.find(n);
  if (it != beds.end()) return it->second;
  const std::string path = bed_cache_path(n);
  Bed bed;
  if (!path.empty() && load_bed(path, n, bed)) {
    std::fprintf(stderr, "bench_step: %zu particles: settled bed from %s (solid fraction %.3f)\n",
                 n, path.c_str(), solid_fraction(bed));
  } else {
    bed = settle(n, model());
    if (!path.empty()) store_bed(path, bed);
  }
  return beds.emplace(n, std::move(bed)).first->second;
}

// One Simulation per (particles, threads), kept across Google Benchmark's repeated calls.
Simulation& bench_simulation(std::size_t n, int threads) {
  static std::map<std::pair<std::size_t, int>, std::unique_ptr<Simulation>> sims;
  auto& sim = sims[{n, threads}];
  if (!sim) {
    const Bed& bed = settled_bed(n);
    const double dt = shortest_collision_time(model()) / kStepsPerCollision;
    sim = make_simulation(model(), dt, threads, bed.box);
    // BENCH_STEP_REORDER=N: Morton-sort the timed bed before every N-th list build (the first
    // build included), as `[simulation] reorder_every` does; the settling is not affected.
    if (const char* r = std::getenv("BENCH_STEP_REORDER")) sim->set_reorder_every(std::atoi(r));
    add_particles(*sim, bed);
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
  state.counters["list_pairs_per_particle"] = pc.first;
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
  const long builds = sim.neighbors().builds;
  for (auto _ : state) {
    sim.request_rebuild();
    sim.step();
  }
  report(state, sim, builds);
}

// 1e4 to 1e6 particles: the cost per particle-step should not grow with the bed (issue 6). The
// 1e5 and 1e6 beds take minutes to settle the first time (bench/README.md; then they are cached).
BENCHMARK(BM_Step)
    ->ArgNames({"particles", "omp_threads"})
    ->ArgsProduct({{10000, 50000, 100000, 1000000}, {1, 2}})
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
  char text[64];
  std::snprintf(text, sizeof text, "%.4g s (t_col/50, t_col = %.4g s)", t_col / kStepsPerCollision,
                t_col);
  benchmark::AddCustomContext("dt", text);
  std::snprintf(text, sizeof text, "%.4g m (0.25 d_min)", kSkinOverDmin * smallest_diameter());
  benchmark::AddCustomContext("skin", text);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
