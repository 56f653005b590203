// SPDX-License-Identifier: MIT
// T-I3 (VERIFICATION.md 4.4): Beverloo-lite. Dry spheres discharge from a flat-bottomed cylinder
// through circular outlets of D/d = 7 and 10. The steady mass flow rate W scales as
// (D - 1.5 d)^2.5, and C = W / (rho_b sqrt(g) (D - 1.5 d)^2.5) lies in the published range
// (Beverloo et al. 1961: C = 0.58; Nedderman 1992: 0.55-0.65; band 0.45-0.75).
//
// Setup: d = 5 mm, rho = 1500, k_n = 1e3 N/m, e = 0.5, mu = 0.5 at particles and walls; a silo of
// 90 mm (18 d) with 3000 spheres, about 11.5 d deep (h/D = 1.6 and 1.15). One fill is settled
// behind a closed floor and its bulk density measured; each outlet run starts from it. Spheres
// 2 d below the floor are removed and put back above the bed, so the head stays constant and a
// 0.2 s window (after 0.05 s; the rate is steady from then on) suffices.
#include <gtest/gtest.h>

#include "assembly.hpp"

namespace silodem {
namespace {

using namespace itest;

struct Bed {
  std::vector<Vec3> x;
  double rho_b = 0.0, z_top = 0.0;
};

struct Flow {
  double rate = 0.0;  // kg/s
  int particles = 0;  // counted in the window
  int escaped = 0;    // found outside the walls (must stay 0)
};

constexpr double kSiloRadius = 45e-3;

// The silo: a cylinder, and a floor that is a full disk (outlet = 0) or an annulus around a
// circular outlet with its rim edge.
void add_silo(Simulation& sim, double outlet_radius) {
  const double R = kSiloRadius;
  sim.add_wall(std::make_unique<FrustumFace>(0.0, 0.0, Meridian{R, 0.0}, Meridian{R, 1.0}, true));
  // A floor face from the rim out to the wall; with inner = true and r increasing, its normal
  // points up (into the silo).
  sim.add_wall(std::make_unique<FrustumFace>(0.0, 0.0, Meridian{outlet_radius, 0.0},
                                             Meridian{R, 0.0}, true));
  if (outlet_radius > 0.0) {
    // The rim: acts where the floor face does not, inside r < outlet_radius.
    sim.add_wall(std::make_unique<CircleEdge>(0.0, 0.0, Meridian{outlet_radius, 0.0},
                                              std::vector<Meridian>{{1.0, 0.0}}));
  }
}

// Discharges the bed through an outlet of diameter D and keeps the inventory constant: particles
// 2 d below the floor are removed and as many are put back, at random, in a layer above the bed.
// W is the mass removed in the 1 ms checks from t_start on, divided by the time they cover
// (about `window`).
Flow discharge(const test::Laws& laws, const Grain& g, const Bed& bed, double D, double t_start,
               double window) {
  auto sim = make_sim(laws, laws, g);
  add_silo(*sim, 0.5 * D);
  ParticleStore& p = sim->particles();
  for (const Vec3& x : bed.x) p.add(x, {}, {}, g.radius(), g.mass(), 0);
  const double R = kSiloRadius, r = g.radius();
  const auto in_silo = [&](const Vec3& x) { return std::hypot(x.x, x.y) < R - r; };
  Random rng(99);
  Flow f;
  double removed_mass = 0.0, t_first = -1.0;
  const long every = std::max(1L, std::lround(1e-3 / sim->dt()));
  std::vector<std::size_t> out;
  while (sim->time() < t_start + window) {
    const double t_before = sim->time();
    sim->run_steps(every);
    out.clear();
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double r_xy = std::hypot(p.x[i].x, p.x[i].y);
      // Outside the cylinder, or below the floor plate away from the outlet: escaped.
      if (r_xy > R + r || (p.x[i].z < 0.0 && r_xy > 0.5 * D + g.d)) ++f.escaped;
      if (p.x[i].z < -2.0 * g.d) out.push_back(i);
    }
    if (t_before >= t_start) {
      if (t_first < 0.0) t_first = t_before;
      removed_mass += static_cast<double>(out.size()) * g.mass();
      f.particles += static_cast<int>(out.size());
    }
    if (out.empty()) continue;
    const int n = static_cast<int>(out.size());
    sim->remove_particles(out);
    const double z0 = bed.z_top + 2.0 * g.d;
    EXPECT_EQ(add_random(*sim, g, {-R, -R, z0}, {R, R, z0 + 4.0 * g.d}, n, rng, in_silo), n);
  }
  f.rate = removed_mass / (sim->time() - t_first);
  return f;
}

TEST(Assembly, TI3_BeverlooScaling) {
  Stopwatch clock;
  const Grain g{5e-3, 1500};
  const test::Laws laws = dry_laws(1e3, 0.5, 0.5);
  // Fill once (closed floor), settle, and measure the bulk density away from walls and surface.
  Bed bed;
  {
    auto sim = make_sim(laws, laws, g);
    add_silo(*sim, 0.0);
    const int n = 3000;
    const double R = kSiloRadius, r = g.radius();
    const double h = n * g.volume() / (0.33 * kPi * R * R);
    Random rng(5);
    ASSERT_EQ(add_random(*sim, g, {-R, -R, r}, {R, R, r + h}, n, rng,
                         [&](const Vec3& x) { return std::hypot(x.x, x.y) < R - r; }),
              n);
    report("fill_settle_s", settle(*sim, 5e-9, 1.0));
    const ParticleStore& p = sim->particles();
    for (const Vec3& x : p.x) bed.z_top = std::max(bed.z_top, x.z);
    const double phi =
        solid_fraction(p, {-R, -R, 2 * g.d}, {R, R, bed.z_top - 3 * g.d}, g.d / 12,
                       [&](const Vec3& x) { return std::hypot(x.x, x.y) < R - 2 * g.d; });
    bed.rho_b = phi * g.rho;
    bed.x = p.x;
    report("bulk_solid_fraction", phi);
    report("bed_height_over_d", bed.z_top / g.d);
  }
  const double ratios[2] = {7.0, 10.0};
  double W[2], C[2];
  for (int k = 0; k < 2; ++k) {
    const double D = ratios[k] * g.d;
    const Flow f = discharge(laws, g, bed, D, 0.05, 0.2);
    W[k] = f.rate;
    C[k] = W[k] / (bed.rho_b * std::sqrt(kG) * std::pow(D - 1.5 * g.d, 2.5));
    const std::string tag = "D_over_d_" + std::to_string(static_cast<int>(ratios[k]));
    report(tag + "_rate_kg_per_s", W[k]);
    report(tag + "_particles_counted", f.particles);
    report(tag + "_beverloo_C", C[k]);
    EXPECT_EQ(f.escaped, 0) << tag;
  }
  const double exponent = std::log(W[1] / W[0]) / std::log((ratios[1] - 1.5) / (ratios[0] - 1.5));
  report("rate_exponent", exponent);
  report("wall_time_s", clock.seconds());
  EXPECT_NEAR(exponent, 2.5, 0.3);
  for (double c : C) {
    EXPECT_GE(c, 0.45);
    EXPECT_LE(c, 0.75);
  }
}

}  // namespace
}  // namespace silodem
