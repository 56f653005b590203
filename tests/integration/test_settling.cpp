// SPDX-License-Identifier: MIT
// T-I1 (VERIFICATION.md 4.4): 2000 frictional spheres (d = 4 mm, rho = 1500, mu_s = 0.5, e = 0.5)
// poured into a 12 d x 12 d box settle to a random packing: solid fraction 0.56-0.64 in the bulk
// (random loose to random close packing), overlaps below 1% of d at k_n = 2e3 N/m, and a kinetic
// energy below 1e-8 J per particle. The pour is a random non-overlapping cloud (solid fraction
// 0.3) that falls onto the floor; a cloud has no lattice order for the bed to inherit.
#include <gtest/gtest.h>

#include "assembly.hpp"

namespace silodem {
namespace {

using namespace itest;

TEST(Assembly, TI1_SettlingInABox) {
  Stopwatch clock;
  const Grain g{4e-3, 1500};
  const double kn = 2e3, e = 0.5, mu_s = 0.5;
  const test::Laws laws = dry_laws(kn, e, mu_s);
  auto sim = make_sim(laws, laws, g);
  const double side = 12 * g.d;
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{side, 0, 0}, Vec3{-1, 0, 0}));
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}));
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, side, 0}, Vec3{0, -1, 0}));
  // A loose random cloud (solid fraction about 0.3) that falls onto the floor.
  const int n = 2000;
  const double h0 = n * g.volume() / (0.3 * side * side);
  Random rng(2024);
  const double r = g.radius();
  ASSERT_EQ(add_random(*sim, g, {r, r, r}, {side - r, side - r, r + h0}, n, rng), n);
  const double t_settle = settle(*sim, 1e-9, 2.0);
  const ParticleStore& p = sim->particles();
  const double ke = kinetic_energy(p) / n;
  double z_top = 0.0;
  for (const Vec3& x : p.x) z_top = std::max(z_top, x.z);
  // Bulk: 2.5 d from the side walls and the floor, 4 d below the highest centre.
  const double m = 2.5 * g.d;
  const double phi = solid_fraction(p, {m, m, m}, {side - m, side - m, z_top - 4 * g.d}, g.d / 16);
  const double overlap = max_overlap(*sim) / g.d;
  report("settle_time_s", t_settle);
  report("bulk_solid_fraction", phi);
  report("max_overlap_over_d", overlap);
  report("kinetic_energy_per_particle_J", ke);
  report("bed_height_over_d", z_top / g.d);
  report("wall_time_s", clock.seconds());
  EXPECT_GE(phi, 0.56);
  EXPECT_LE(phi, 0.64);
  EXPECT_LT(overlap, 0.01);
  EXPECT_LT(ke, 1e-8);
}

}  // namespace
}  // namespace silodem
