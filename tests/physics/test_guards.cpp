// SPDX-License-Identifier: MIT
// Guards during a run (issue 5): a time step far above the collision time, a particle placed
// inside a wall, a NaN injected, a particle faster than the bound. Each stops the run with a
// diagnostic naming the step, the particle, its position and velocity, and the likely cause.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "helpers.hpp"

namespace silodem {
namespace {

constexpr double kR = 4e-3, kM = 4e-4;

std::string run_until_error(Simulation& sim, long steps) {
  try {
    sim.run_steps(steps);
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "no error";
}

Simulation make(double dt_over_tcol, double max_speed = 0.0) {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  ContactModel model = test::model_of(l);
  const double t_col = model.pair_collision_time(0, 0, kM, kM, kR, kR);
  SimulationSettings s;
  s.dt = dt_over_tcol * t_col;
  s.gravity = {};
  s.threads = 1;
  s.max_speed = max_speed;
  return Simulation(std::move(model), s);
}

TEST(Guards, TimeStepFarAboveTheCollisionTime) {
  // A particle squeezed between two walls by 1% of its radius on each side. At dt = 3 t_col
  // (omega dt > 2) velocity Verlet is unstable: the oscillation grows every step until the
  // overlap guard stops it.
  auto squeezed = [](double dt_over_tcol) {
    Simulation sim = make(dt_over_tcol);
    sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
    sim.add_wall(std::make_unique<PlaneWall>(Vec3{2 * kR * 0.99, 0, 0}, Vec3{-1, 0, 0}));
    sim.particles().add({kR * 0.99 + 1e-5, 0, 0}, {}, {}, kR, kM, 0);
    return sim;
  };
  Simulation sim = squeezed(3.0);
  const std::string e = run_until_error(sim, 2000);
  EXPECT_NE(e.find("guard at step"), std::string::npos) << e;
  EXPECT_NE(e.find("collision time"), std::string::npos) << e;
  EXPECT_NE(e.find("x this particle's collision time"), std::string::npos) << e;
  // The same particle at dt = t_col / 50 settles in the middle.
  Simulation ok = squeezed(1.0 / 50.0);
  EXPECT_EQ(run_until_error(ok, 2000), "no error");
}

TEST(Guards, ParticlePlacedInsideAWall) {
  Simulation sim = make(1.0 / 50.0);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.particles().add({0.01, 0.02, 0.2 * kR}, {}, {}, kR, kM, 0);  // overlap 0.8 R
  const std::string e = run_until_error(sim, 1);
  EXPECT_NE(e.find("overlap guard at step 0"), std::string::npos) << e;
  EXPECT_NE(e.find("particle 0 at (0.01, 0.02, 0.0008)"), std::string::npos) << e;
  EXPECT_NE(e.find("wall 0 by 0.0032 m = 0.80 of its radius"), std::string::npos) << e;
  EXPECT_NE(e.find("placed inside a wall"), std::string::npos) << e;
  // At 0.4 R the same placement is a (hard) contact, not an error.
  Simulation ok = make(1.0 / 50.0);
  ok.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  ok.particles().add({0.01, 0.02, 0.6 * kR}, {}, {}, kR, kM, 0);
  EXPECT_EQ(run_until_error(ok, 1), "no error");
}

TEST(Guards, NaNInjectedIsCaughtWithin256Steps) {
  Simulation sim = make(1.0 / 50.0);
  sim.particles().add({0, 0, 0}, {}, {}, kR, kM, 0);
  sim.particles().add({0.1, 0, 0}, {0.1, 0, 0}, {}, kR, kM, 0);
  sim.add_hook({"inject", Phase::StepEnd, 1, [](Simulation& s) {
                  if (s.step_count() == 300)
                    s.particles().v[1].y = std::numeric_limits<double>::quiet_NaN();
                }});
  const std::string e = run_until_error(sim, 2000);
  EXPECT_NE(e.find("particle 1 has a non-finite state at step 512"), std::string::npos) << e;
}

TEST(Guards, ParticleFasterThanTheBound) {
  Simulation sim = make(1.0 / 50.0, 3.0);
  sim.particles().add({0, 0, 0}, {0, 0, -2.5}, {}, kR, kM, 0);
  sim.set_gravity({0, 0, -9.81});
  // 2.5 m/s + 9.81 m/s^2 t passes 3 m/s after 51 ms; the check runs every 256 steps.
  const std::string e = run_until_error(sim, 100000);
  EXPECT_NE(e.find("speed guard at step"), std::string::npos) << e;
  EXPECT_NE(e.find("above the bound 3 m/s"), std::string::npos) << e;
  EXPECT_NEAR(sim.time(), 0.051, 256 * sim.dt() + 1e-9);
}

}  // namespace
}  // namespace silodem
