// SPDX-License-Identifier: MIT
// Helpers of the small-assembly tests (VERIFICATION.md 4.4): soft, dry grains, simulations with
// dt = t_col/50 and two threads, random deposition without overlaps, and bulk measurements
// (kinetic energy, largest overlap, solid fraction in a sub-volume). Every measured number is
// printed and also recorded as a GoogleTest property, so a run with --gtest_output=json keeps it.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "../physics/helpers.hpp"
#include "core/random.hpp"
#include "engine/simulation.hpp"
#include "engine/walls/frustum.hpp"
#include "engine/walls/plane.hpp"

namespace silodem::itest {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;

struct Grain {
  double d = 4e-3;    // m
  double rho = 1500;  // kg/m^3
  double radius() const { return 0.5 * d; }
  double volume() const { return kPi / 6.0 * d * d * d; }
  double mass() const { return rho * volume(); }
};

// Linear spring-dashpot, tangential spring with Coulomb cap, optional rolling law; no cohesion.
inline test::Laws dry_laws(double kn, double e, double mu_s, const std::string& rolling = "none",
                           double mu_r = 0.0) {
  test::Laws l;
  l.normal_p = {{"stiffness", kn}, {"restitution", e}};
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", mu_s}};
  l.rolling = rolling;
  if (rolling != "none") l.rolling_p = {{"friction", mu_r}};
  return l;
}

// One material; dt = t_col,pp / 50 (the shortest collision time: m_eff = m/2), two threads.
inline std::unique_ptr<Simulation> make_sim(const test::Laws& particle, const test::Laws& wall,
                                            const Grain& g, double skin_over_d = 0.25) {
  ContactModel model = test::model_of(particle, {0.0}, &wall);
  SimulationSettings s;
  s.dt = model.pair_collision_time(0, 0, g.mass(), g.mass(), g.radius(), g.radius()) / 50.0;
  s.gravity = {0.0, 0.0, -kG};
  s.skin = skin_over_d * g.d;
  s.threads = 2;
  return std::make_unique<Simulation>(std::move(model), s);
}

// Bins of a uniform hash grid for overlap-free random placement and point sampling.
class PointGrid {
 public:
  explicit PointGrid(double cell) : cell_(cell) {}
  void insert(const Vec3& x, std::size_t i) { cells_[key(x, 0, 0, 0)].push_back(i); }
  // Calls f(i) for every stored index in the 27 cells around x.
  template <class F>
  void around(const Vec3& x, F&& f) const {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(key(x, dx, dy, dz));
          if (it == cells_.end()) continue;
          for (std::size_t i : it->second) f(i);
        }
  }

 private:
  long long key(const Vec3& x, int dx, int dy, int dz) const {
    const auto c = [&](double v, int o) {
      return static_cast<long long>(std::floor(v / cell_)) + o;
    };
    return ((c(x.x, dx) + 4096) * 8192 + (c(x.y, dy) + 4096)) * 8192 + (c(x.z, dz) + 4096);
  }
  double cell_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

// Random sequential addition: up to n spheres at rest with centres uniform in the box [lo, hi]
// where inside(x) holds, none overlapping each other or the particles already present. Returns
// how many were placed (fewer if two million candidates were not enough).
inline int add_random(Simulation& sim, const Grain& g, const Vec3& lo, const Vec3& hi, int n,
                      Random& rng, const std::function<bool(const Vec3&)>& inside = {}) {
  ParticleStore& p = sim.particles();
  const double min_dist = g.d;
  const long attempts = 2000000;
  PointGrid grid(min_dist);
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(p.x[i], i);
  std::vector<Vec3> placed;
  int added = 0;
  for (long a = 0; a < attempts && added < n; ++a) {
    const Vec3 x{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y), rng.uniform(lo.z, hi.z)};
    if (inside && !inside(x)) continue;
    bool free = true;
    grid.around(x, [&](std::size_t i) {
      const Vec3 other = i < p.size() ? p.x[i] : placed[i - p.size()];
      if (norm2(other - x) < min_dist * min_dist) free = false;
    });
    if (!free) continue;
    grid.insert(x, p.size() + placed.size());
    placed.push_back(x);
    ++added;
  }
  for (const Vec3& x : placed) p.add(x, {}, {}, g.radius(), g.mass(), 0);
  sim.request_rebuild();
  return added;
}

inline double kinetic_energy(const ParticleStore& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    e += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 / p.inv_inertia[i] * norm2(p.omega[i]);
  return e;
}

// Largest particle-particle or particle-wall overlap (m). The neighbour list holds every pair
// closer than the cut-off plus the skin, so every overlapping pair is in it.
inline double max_overlap(const Simulation& sim) {
  const ParticleStore& p = sim.particles();
  const VerletList& nl = sim.neighbors();
  double worst = 0.0;
  for (std::size_t i = 0; i + 1 < nl.offset.size(); ++i) {
    for (int e = nl.offset[i]; e < nl.offset[i + 1]; ++e) {
      const auto j = static_cast<std::size_t>(nl.partner[e]);
      worst = std::max(worst, p.radius[i] + p.radius[j] - norm(p.x[i] - p.x[j]));
    }
    for (const auto& w : sim.walls()) {
      WallHit hit;
      if (w->enabled && w->near(p.x[i], p.radius[i], hit))
        worst = std::max(worst, p.radius[i] - hit.distance);
    }
  }
  return worst;
}

// Solid fraction inside the box [lo, hi] (and where inside(x) holds): the share of a regular grid
// of sample points (spacing about `h`) that lies inside some sphere.
inline double solid_fraction(const ParticleStore& p, const Vec3& lo, const Vec3& hi, double h,
                             const std::function<bool(const Vec3&)>& inside = {}) {
  double r_max = 0.0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  PointGrid grid(2.0 * r_max);
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(p.x[i], i);
  const auto count = [&](double a, double b) { return std::max(1L, std::lround((b - a) / h)); };
  const long nx = count(lo.x, hi.x), ny = count(lo.y, hi.y), nz = count(lo.z, hi.z);
  long in = 0, total = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) {
        const Vec3 x{
            lo.x + (static_cast<double>(i) + 0.5) * (hi.x - lo.x) / static_cast<double>(nx),
            lo.y + (static_cast<double>(j) + 0.5) * (hi.y - lo.y) / static_cast<double>(ny),
            lo.z + (static_cast<double>(k) + 0.5) * (hi.z - lo.z) / static_cast<double>(nz)};
        if (inside && !inside(x)) continue;
        ++total;
        bool hit = false;
        grid.around(x, [&](std::size_t q) {
          if (!hit && norm2(p.x[q] - x) < p.radius[q] * p.radius[q]) hit = true;
        });
        in += hit ? 1 : 0;
      }
  return total > 0 ? static_cast<double>(in) / static_cast<double>(total) : 0.0;
}

// Runs in chunks of `chunk` seconds until the kinetic energy per particle is below
// `ke_per_particle` (or t_max is reached); returns the simulated time used.
inline double settle(Simulation& sim, double ke_per_particle, double t_max, double chunk = 0.01) {
  const double t0 = sim.time();
  while (sim.time() - t0 < t_max) {
    sim.run_until(sim.time() + chunk);
    const auto n = static_cast<double>(std::max<std::size_t>(1, sim.particles().size()));
    if (kinetic_energy(sim.particles()) / n < ke_per_particle) break;
  }
  return sim.time() - t0;
}

// Wall-clock seconds since construction.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Prints a measured number and records it as a test property.
inline void report(const std::string& key, double value) {
  std::printf("  [measured] %s = %.6g\n", key.c_str(), value);
  std::fflush(stdout);
  ::testing::Test::RecordProperty(key, std::to_string(value));
}

}  // namespace silodem::itest
