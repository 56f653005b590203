// SPDX-License-Identifier: MIT
// T-I6 (VERIFICATION.md 4.4): repose-angle trend. A block of 1500 spheres (d = 5 mm, 40 d wide,
// about 11 d high) between two parallel planes 3 d apart (a quasi-2D slab) is released and slumps
// into a heap on a flat floor. With the elastic-plastic rolling law "epsd" (Ai et al. 2011, type
// C) the heap angle does not decrease as mu_r grows (Zhou et al. 1999, 2002: the angle rises with
// mu_r and saturates), within +-1 degree of noise. Every run starts from the same settled block;
// the same laws act at the walls. The angle is taken 0.35 s after the release (it changed by less
// than 1 degree between 0.3 and 0.4 s in trial runs); with mu_r = 0 a few spheres keep rolling
// away on the floor, far from the flanks that are measured.
#include <gtest/gtest.h>

#include "assembly.hpp"

namespace silodem {
namespace {

using namespace itest;

constexpr double kSlab = 3;        // slab thickness in diameters
constexpr double kHalfWidth = 20;  // block half-width in diameters

void add_slab(Simulation& sim, const Grain& g) {
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, kSlab * g.d, 0}, Vec3{0, -1, 0}));
}

// Heap angle (degrees): the surface height in bins of width d along x, and on each flank a
// least-squares line through the bins between 20% and 80% of the peak height; the mean of both.
double heap_angle(const ParticleStore& p, const Grain& g) {
  const int bins = 200;
  const double x0 = -0.5 * bins * g.d;
  std::vector<double> h(bins, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const long b = std::lround(std::floor((p.x[i].x - x0) / g.d));
    if (b >= 0 && b < bins) h[b] = std::max(h[b], p.x[i].z + p.radius[i]);
  }
  const double top = *std::max_element(h.begin(), h.end());
  double angle = 0.0;
  for (int side : {-1, 1}) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int b = 0; b < bins; ++b) {
      const double x = x0 + (b + 0.5) * g.d;
      if (x * side <= 0 || h[b] < 0.2 * top || h[b] > 0.8 * top) continue;
      const double u = std::fabs(x);
      sx += u, sy += h[b], sxx += u * u, sxy += u * h[b], ++n;
    }
    if (n < 3) return std::nan("");  // no flank to measure
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    angle += 0.5 * std::atan(-slope) * 180.0 / kPi;
  }
  return angle;
}

TEST(Assembly, TI6_ReposeTrendWithRollingFriction) {
  Stopwatch clock;
  const Grain g{5e-3, 1500};
  const double kn = 1e3, e = 0.5, mu_s = 0.5;
  // The block: 1500 spheres settled between the slab planes and two end planes.
  std::vector<Vec3> block;
  {
    // Preparation only: strong damping (e = 0.1) settles the block sooner.
    const test::Laws laws = dry_laws(kn, 0.1, mu_s);
    auto sim = make_sim(laws, laws, g);
    add_slab(*sim, g);
    const double w = kHalfWidth * g.d;
    sim->add_wall(std::make_unique<PlaneWall>(Vec3{-w, 0, 0}, Vec3{1, 0, 0}));
    sim->add_wall(std::make_unique<PlaneWall>(Vec3{w, 0, 0}, Vec3{-1, 0, 0}));
    const int n = 1500;
    const double r = g.radius(), h = n * g.volume() / (0.25 * 2 * w * kSlab * g.d);
    Random rng(11);
    ASSERT_EQ(add_random(*sim, g, {-w + r, r, r}, {w - r, kSlab * g.d - r, r + h}, n, rng), n);
    report("block_settle_s", settle(*sim, 5e-9, 1.0));
    block = sim->particles().x;
  }
  const double mu_r[3] = {0.0, 0.05, 0.2};
  double angle[3];
  for (int k = 0; k < 3; ++k) {
    const test::Laws laws = dry_laws(kn, e, mu_s, "epsd", mu_r[k]);
    auto sim = make_sim(laws, laws, g);
    add_slab(*sim, g);
    for (const Vec3& x : block) sim->particles().add(x, {}, {}, g.radius(), g.mass(), 0);
    sim->run_until(0.25);
    const double angle_early = heap_angle(sim->particles(), g);
    sim->run_until(0.35);
    angle[k] = heap_angle(sim->particles(), g);
    char tag[32];
    std::snprintf(tag, sizeof tag, "mu_r_%.2f", mu_r[k]);
    report(std::string(tag) + "_angle_at_0.25s_deg", angle_early);
    report(std::string(tag) + "_angle_deg", angle[k]);
    report(std::string(tag) + "_ke_per_particle_J",
           kinetic_energy(sim->particles()) / static_cast<double>(block.size()));
  }
  report("wall_time_s", clock.seconds());
  EXPECT_GE(angle[1], angle[0] - 1.0);
  EXPECT_GE(angle[2], angle[1] - 1.0);
}

}  // namespace
}  // namespace silodem
