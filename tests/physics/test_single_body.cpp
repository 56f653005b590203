// SPDX-License-Identifier: MIT
// T-P1 free fall and T-P2 bouncing particle (MFIX DEM02), VERIFICATION.md 4.2.
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"

namespace silodem {
namespace {

TEST(SingleBody, TP1_FreeFallIsExact) {
  test::Laws l;
  SimulationSettings s;
  s.dt = 1e-3;
  s.threads = 1;
  Simulation sim(test::model_of(l), s);
  sim.particles().add({0, 0, 10.0}, {}, {}, 0.01, 1e-3, 0);
  sim.run_until(1.0);
  const double t = sim.time();
  EXPECT_NEAR(t, 1.0, 1e-9);
  EXPECT_NEAR(sim.particles().x[0].z / (10.0 - 0.5 * 9.81 * t * t), 1.0, 1e-10);
  EXPECT_NEAR(sim.particles().v[0].z / (-9.81 * t), 1.0, 1e-10);
}

// Maximum centre heights after the first three bounces.
std::vector<double> bounce_peaks(double e, double kn) {
  const double d = 0.2, rho = 2600, r = 0.1, h0 = 0.5;
  const double m = test::sphere_mass_of(d, rho);
  test::Laws l;
  l.normal_p = {{"stiffness", kn}, {"restitution", e}};
  ContactModel model = test::model_of(l);
  SimulationSettings s;
  s.dt = model.wall_collision_time(0, m, r) / 50.0;
  s.threads = 1;
  s.skin = 0.02;
  Simulation sim(std::move(model), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.particles().add({0, 0, h0}, {}, {}, r, m, 0);
  std::vector<double> peaks;
  double prev_v = 0.0, z_max = 0.0;
  bool rising = false;
  while (peaks.size() < 3 && sim.time() < 5.0) {
    sim.step();
    const double v = sim.particles().v[0].z, z = sim.particles().x[0].z;
    if (v > 0) rising = true, z_max = std::max(z_max, z);
    if (rising && prev_v > 0 && v <= 0) {
      peaks.push_back(z_max);
      rising = false;
      z_max = 0.0;
    }
    prev_v = v;
  }
  return peaks;
}

TEST(SingleBody, TP2_BouncingParticleDem02) {
  for (double e : {0.5, 0.7, 0.9}) {
    const auto soft = bounce_peaks(e, 5e5), stiff = bounce_peaks(e, 5e6);
    ASSERT_EQ(stiff.size(), 3u);
    ASSERT_EQ(soft.size(), 3u);
    double err_soft = 0, err_stiff = 0;
    for (int k = 1; k <= 3; ++k) {
      const double want = (0.5 - 0.1) * std::pow(e, 2 * k) + 0.1;  // h_k = (h0 - r) e^2k + r
      err_stiff = std::max(err_stiff, std::fabs(stiff[k - 1] / want - 1.0));
      err_soft = std::max(err_soft, std::fabs(soft[k - 1] / want - 1.0));
    }
    EXPECT_LT(err_stiff, 0.02) << "e = " << e;
    EXPECT_LT(err_stiff, err_soft) << "the error must fall as k_n rises, e = " << e;
  }
}

}  // namespace
}  // namespace silodem
