// SPDX-License-Identifier: MIT
// T-I2 (VERIFICATION.md 4.4): Janssen's saturation of the apparent mass in a cylinder. A cylinder
// D = 48 mm (D/d = 12) with a floor is filled in stages; after each stage has settled the floor
// is "weighed". The apparent masses follow M_app = M_sat (1 - exp(-M / M_sat)) (Janssen 1895;
// Landry et al. 2003), and K = rho_b pi D^3 / (16 mu_w M_sat) lies in the DEM range.
#include <gtest/gtest.h>

#include "assembly.hpp"

namespace silodem {
namespace {

using namespace itest;

// A horizontal floor at height z moving with vertical velocity vz (set by the test).
class MovingFloor final : public Wall {
 public:
  double z = 0.0, vz = 0.0;
  bool near(const Vec3& c, double limit, WallHit& hit) const override {
    const double d = c.z - z;
    if (d >= limit) return false;
    hit.n = {0.0, 0.0, 1.0};
    hit.distance = d;
    return true;
  }
  Vec3 velocity() const override { return {0.0, 0.0, vz}; }
  std::string describe() const override { return "moving floor"; }
};

// Least-squares M_sat of M_app = M_sat (1 - exp(-M / M_sat)) (golden-section search on the
// residual, which has one minimum in M_sat > 0) and the fit's R^2.
struct JanssenFit {
  double m_sat = 0.0, r2 = 0.0;
};

JanssenFit fit_janssen(const std::vector<double>& m, const std::vector<double>& m_app) {
  const auto sse = [&](double ms) {
    double s = 0.0;
    for (std::size_t k = 0; k < m.size(); ++k) {
      const double r = m_app[k] - ms * (1.0 - std::exp(-m[k] / ms));
      s += r * r;
    }
    return s;
  };
  double a = 1e-3 * m.back(), b = 1e3 * m.back();
  const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200; ++it) {
    const double c = b - phi * (b - a), d = a + phi * (b - a);
    if (sse(c) < sse(d))
      b = d;
    else
      a = c;
  }
  JanssenFit f;
  f.m_sat = 0.5 * (a + b);
  double mean = 0.0;
  for (double v : m_app) mean += v / static_cast<double>(m_app.size());
  double sst = 0.0;
  for (double v : m_app) sst += (v - mean) * (v - mean);
  f.r2 = 1.0 - sse(f.m_sat) / sst;
  return f;
}

TEST(Assembly, TI2_JanssenSaturation) {
  Stopwatch clock;
  const Grain g{4e-3, 1500};
  const double kn = 1e3, e = 0.3, mu = 0.5;  // mu_w = mu_s
  const test::Laws laws = dry_laws(kn, e, mu);
  auto sim = make_sim(laws, laws, g);
  const double D = 48e-3, R = 0.5 * D, r = g.radius();
  // The cylinder reaches below the floor, which moves down slowly during each weighing.
  sim->add_wall(std::make_unique<FrustumFace>(0.0, 0.0, Meridian{R, -0.05}, Meridian{R, 1.0}, true));
  auto floor_owner = std::make_unique<MovingFloor>();
  MovingFloor* floor = floor_owner.get();
  sim->add_wall(std::move(floor_owner));
  const auto in_cylinder = [&](const Vec3& x) { return std::hypot(x.x, x.y) < R - r - 0.02 * g.d; };
  const ParticleStore& p = sim->particles();
  Random rng(7);
  const int stages = 5, per_stage = 700;
  std::vector<double> mass, apparent;
  for (int s = 0; s < stages; ++s) {
    double z_top = floor->z;
    for (const Vec3& x : p.x) z_top = std::max(z_top, x.z);
    add_lattice(*sim, g, {-R, -R, z_top + g.d}, {R, R, 0}, 1.04 * g.d, 0.02 * g.d, per_stage, rng,
                in_cylinder);
    const double t_settle = settle(*sim, 5e-9, 1.0);
    // Weigh while the floor moves down slowly, so that the wall friction is fully mobilised
    // upwards (Vanel & Clement 1999; Ovarlez et al. 2003): 0.01 m/s for 30 ms; the floor force
    // (its elastic part; the particles move with the floor) is averaged over the last 15 ms.
    floor->vz = -0.01;
    double f_floor = 0.0;
    int samples = 0;
    const double t0 = sim->time();
    while (sim->time() - t0 < 0.03) {
      floor->z += floor->vz * sim->dt();
      sim->step();
      if (sim->time() - t0 < 0.015) continue;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double ov = p.radius[i] - (p.x[i].z - floor->z);
        if (ov > 0) f_floor += kn * ov;
      }
      ++samples;
    }
    f_floor /= samples;
    floor->vz = 0.0;
    report("stage" + std::to_string(s + 1) + "_settle_s", t_settle);
    mass.push_back(static_cast<double>(p.size()) * g.mass());
    apparent.push_back(f_floor / kG);
    report("stage" + std::to_string(s + 1) + "_mass_kg", mass.back());
    report("stage" + std::to_string(s + 1) + "_apparent_over_mass", apparent.back() / mass.back());
    report("stage" + std::to_string(s + 1) + "_time_s", sim->time());
  }
  double z_top = floor->z;
  for (const Vec3& x : p.x) z_top = std::max(z_top, x.z);
  // Column-average bulk density: the whole cross-section, away from the floor and the surface.
  const double phi = solid_fraction(p, {-R, -R, floor->z + 2 * g.d}, {R, R, z_top - 4 * g.d}, g.d / 12,
                                    [&](const Vec3& x) { return std::hypot(x.x, x.y) < R; });
  const double rho_b = phi * g.rho;
  const JanssenFit fit = fit_janssen(mass, apparent);
  const double K = rho_b * kPi * D * D * D / (16.0 * mu * fit.m_sat);
  const double lambda = D / (4.0 * mu * K);
  report("column_solid_fraction", phi);
  report("fill_height_over_lambda", (z_top + r - floor->z) / lambda);
  report("m_sat_kg", fit.m_sat);
  report("fit_r2", fit.r2);
  report("janssen_K", K);
  report("final_apparent_over_mass", apparent.back() / mass.back());
  report("wall_time_s", clock.seconds());
  EXPECT_GT(fit.r2, 0.98);
  EXPECT_LT(apparent.back(), 0.9 * mass.back());
  EXPECT_GE(K, 0.3);
  EXPECT_LE(K, 0.9);
}

}  // namespace
}  // namespace silodem
