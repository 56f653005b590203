// SPDX-License-Identifier: MIT
// T-P9 (VERIFICATION.md 4.2): elastic, frictionless spheres in a closed box conserve energy with
// velocity Verlet, and the error is second order in dt.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"
#include "helpers.hpp"

namespace silodem {
namespace {

double max_energy_error(double dt_factor, long steps) {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e3}, {"restitution", 1.0}};
  const double r = 2e-3, m = test::sphere_mass_of(2 * r, 1500), box = 0.04;
  ContactModel model = test::model_of(l);
  SimulationSettings s;
  s.dt = model.pair_collision_time(0, 0, m, m, r, r) / dt_factor;
  s.gravity = {};
  s.threads = 1;
  s.skin = 0.5 * r;
  Simulation sim(std::move(model), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{box, 0, 0}, Vec3{-1, 0, 0}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 1, 0}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, box, 0}, Vec3{0, -1, 0}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, box}, Vec3{0, 0, -1}));
  Random rng(42);
  // 300 spheres on a 7x7x7 lattice (spacing 5.5 mm) with random velocities.
  int n = 0;
  for (int i = 0; i < 7 && n < 300; ++i)
    for (int j = 0; j < 7 && n < 300; ++j)
      for (int k = 0; k < 7 && n < 300; ++k, ++n) {
        const Vec3 x{3.5e-3 + i * 5.5e-3, 3.5e-3 + j * 5.5e-3, 3.5e-3 + k * 5.5e-3};
        const Vec3 v{rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)};
        sim.particles().add(x, v, {}, r, m, 0);
      }
  sim.initialize();
  const double e0 = sim.energy().total();
  double worst = 0.0;
  for (long k = 0; k < steps; k += 50) {
    sim.run_steps(50);
    worst = std::max(worst, std::fabs(sim.energy().total() - e0) / e0);
  }
  return worst;
}

TEST(Energy, TP9_DriftAndSecondOrder) {
  const double coarse = max_energy_error(50, 100000);
  const double fine = max_energy_error(100, 200000);
  EXPECT_LT(coarse, 1e-3);
  const double ratio = coarse / fine;
  EXPECT_GT(ratio, 3.0) << coarse << " " << fine;
  EXPECT_LT(ratio, 5.0) << coarse << " " << fine;
}

// The force pass, the contact tally and the energy visit a particle's wall contacts through one
// loop with one rule (engine/contact_visit.hpp): a wall switched off takes part in none of them,
// even before the list is rebuilt. A sphere pressed 0.1 mm into a plane stores 1/2 k_n delta^2
// of elastic energy (exact for the linear spring) until the plane is switched off.
TEST(Energy, ASwitchedOffWallStoresNoEnergyAndMakesNoContact) {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e3}, {"restitution", 1.0}};
  const double r = 2e-3, m = test::sphere_mass_of(2 * r, 1500), delta = 1e-4;
  ContactModel model = test::model_of(l);
  SimulationSettings s;
  s.dt = model.wall_collision_time(0, m, r) / 50;
  s.gravity = {};
  s.threads = 1;
  s.skin = 0.5 * r;
  Simulation sim(std::move(model), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.particles().add({0, 0, r - delta}, {}, {}, r, m, 0);
  sim.initialize();
  EXPECT_NEAR(sim.energy().elastic, 0.5 * 1e3 * delta * delta, 1e-12 * 1e3 * delta * delta);
  EXPECT_EQ(sim.contact_tally().wall_contacts[0], 1);
  sim.set_wall_enabled(0, false);  // the list still holds the contact until the next step
  ASSERT_EQ(sim.neighbors().wall.size(), 1u);
  EXPECT_EQ(sim.energy().elastic, 0.0);
  EXPECT_EQ(sim.contact_tally().wall_contacts[0], 0);
  sim.step();
  EXPECT_EQ(sim.particles().f[0].z, 0.0);  // no force from the switched-off wall
}

}  // namespace
}  // namespace silodem
