// SPDX-License-Identifier: MIT
// Probes against known answers (issue 4): a bed at rest (zero velocity, level = its height,
// coordination of a cubic lattice), a chain of cohesive particles (100% adhered, mean cohesive
// force = the analytic sum), a single particle at a known speed in the right profile bin.
#include <gtest/gtest.h>

#include <cmath>

#include "../../physics/helpers.hpp"
#include "probes/registry.hpp"

namespace silodem {
namespace {

constexpr double kR = 4.0e-3;  // m
constexpr double kM = 4.0e-4;  // kg
constexpr double kF = 0.05;    // N, F_L,cg of the chain's coal

std::unique_ptr<Simulation> empty_sim(double cohesion = 0.0) {
  test::Laws l;
  if (cohesion > 0) l.cohesion = "overlap-only";
  SimulationSettings s;
  s.dt = 1e-6;
  s.gravity = {};
  s.threads = 1;
  return std::make_unique<Simulation>(test::model_of(l, {cohesion}), s);
}

// What a case tells the probes. The site defaults to the paper's silo (cylinder 468 mm wide).
struct Given {
  ProbeSpec probes;
  ProbeSite site{0.234};
};

std::unique_ptr<Probe> probe(const Given& c, const std::string& name) {
  for (const auto& e : probe_registry())
    if (e.name == name) return e.make(c.probes, c.site);
  ADD_FAILURE() << "no probe " << name;
  return nullptr;
}

std::vector<ProbeRow> sample(Probe& p, const Simulation& sim, double t, int times = 1) {
  std::vector<ProbeRow> rows;
  for (int k = 0; k < times; ++k) {
    ProbeView v(sim, t);
    p.sample(v, rows);
  }
  return rows;
}

// n x n x n simple cubic lattice, spacing slightly below 2r (every neighbour pair touches),
// resting on z = 0 (bottom centres at z = r), centred on the axis.
std::unique_ptr<Simulation> cubic_bed(int n, double* top) {
  auto sim = empty_sim();
  const double a = 2 * kR * (1 - 1e-6);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        sim->particles().add({(i - 0.5 * (n - 1)) * a, (j - 0.5 * (n - 1)) * a, kR + k * a}, {}, {},
                             kR, kM, 0);
  sim->initialize();
  *top = kR + (n - 1) * a + kR;
  return sim;
}

TEST(Probes, BedAtRestHasZeroVelocityAndItsLevel) {
  double top = 0;
  auto sim = cubic_bed(5, &top);
  Given c;
  c.probes.profile_heights = {kR, kR + 2 * 2 * kR};  // the first and the third layer
  c.probes.profile_bin = 2 * kR;
  c.probes.slab_thickness = 2 * kR;  // the middle row of the lattice only
  auto level = probe(c, "level");
  const auto lv = sample(*level, *sim, 0.5);
  ASSERT_EQ(lv.size(), 1u);
  EXPECT_DOUBLE_EQ(lv[0][0], 0.5);
  EXPECT_NEAR(lv[0][1], top, 1e-12);

  auto prof = probe(c, "velocity_profile");
  sample(*prof, *sim, 0.0, 4);
  std::vector<ProbeRow> rows;
  prof->finish(rows);
  int filled = 0;
  for (const auto& r : rows) {
    if (r[4] == 0) continue;  // samples
    ++filled;
    EXPECT_EQ(r[2], 0.0) << "height " << r[0] << " x " << r[1];
    EXPECT_EQ(r[3], 0.0);
    EXPECT_EQ(r[4], 4.0);  // one particle per bin (middle row), four samples
  }
  EXPECT_EQ(filled, 2 * 5);  // five columns at each of the two heights

  // Coordination of a cubic lattice: 3 n^2 (n - 1) bonds, each counted at both ends.
  auto coord = probe(c, "coordination");
  const auto cr = sample(*coord, *sim, 0.0);
  EXPECT_EQ(cr[0][1], 125.0);
  EXPECT_NEAR(cr[0][2], 2.0 * 3 * 25 * 4 / 125.0, 1e-12);
}

TEST(Probes, CohesiveChainIsFullyAdheredWithTheAnalyticMeanForce) {
  auto sim = empty_sim(kF);
  const int n = 6;
  for (int i = 0; i < n; ++i)
    sim->particles().add({i * 2 * kR * (1 - 1e-4), 0, 0.1}, {}, {}, kR, kM, 0);
  sim->initialize();
  Given c;
  auto adh = probe(c, "adhesion");
  const auto a = sample(*adh, *sim, 0.0);
  EXPECT_EQ(a[0][1], double(n));
  EXPECT_EQ(a[0][2], double(n));
  EXPECT_EQ(a[0][3], 1.0);
  // Overlap-only cohesion: F_L,cg on every touching pair; ends have one bond, the rest two.
  auto coh = probe(c, "cohesion_force");
  const auto f = sample(*coh, *sim, 0.0);
  EXPECT_NEAR(f[0][2], 2.0 * (n - 1) * kF / n, 1e-12);
  EXPECT_NEAR(f[0][3], 2.0 * kF, 1e-12);
  // A threshold above the bond force: nobody is held.
  c.probes.adhesion_threshold = 1.01 * kF;
  auto strict = probe(c, "adhesion");
  EXPECT_EQ(sample(*strict, *sim, 0.0)[0][3], 0.0);
}

TEST(Probes, SeparatedParticlesAreNotAdhered) {
  auto sim = empty_sim(kF);
  sim->particles().add({0, 0, 0.1}, {}, {}, kR, kM, 0);
  sim->particles().add({2 * kR * 1.01, 0, 0.1}, {}, {}, kR, kM, 0);
  sim->initialize();
  Given c;
  auto adh = probe(c, "adhesion");
  EXPECT_EQ(sample(*adh, *sim, 0.0)[0][2], 0.0);
  auto coh = probe(c, "cohesion_force");
  EXPECT_EQ(sample(*coh, *sim, 0.0)[0][2], 0.0);
}

TEST(Probes, MovingParticleLandsInItsProfileBinWithItsVelocity) {
  auto sim = empty_sim();
  const double x0 = 0.0437, h = 0.2, vz = -0.31;
  sim->particles().add({x0, 0.001, h + 0.002}, {0.05, 0, vz}, {}, kR, kM, 0);
  sim->initialize();
  Given c;
  c.site.silo_radius = 0.1;  // bins from x = -0.1 m
  c.probes.profile_bin = 0.01;
  c.probes.profile_heights = {0.1, 0.2, 0.3};
  c.probes.profile_from = 1.0;
  c.probes.profile_to = 2.0;
  auto prof = probe(c, "velocity_profile");
  sample(*prof, *sim, 0.5, 2);  // before the window: not counted
  sample(*prof, *sim, 1.5, 3);
  std::vector<ProbeRow> rows;
  prof->finish(rows);
  ASSERT_EQ(rows.size(), 3u * 20u);
  int hits = 0;
  for (const auto& r : rows) {
    if (r[4] == 0) continue;
    ++hits;
    EXPECT_DOUBLE_EQ(r[0], h);
    EXPECT_NEAR(r[1], 0.045, 1e-12);  // the bin [0.04, 0.05)
    EXPECT_DOUBLE_EQ(r[2], vz);
    EXPECT_EQ(r[4], 3.0);
    EXPECT_DOUBLE_EQ(r[5], 1.5);
  }
  EXPECT_EQ(hits, 1);
}

TEST(Probes, SlabSnapshotsAtTheirTimesOnlyInsideTheSlab) {
  auto sim = empty_sim();
  sim->particles().add({0.01, 0.004, 0.1}, {}, {}, kR, kM, 0);   // inside |y| <= 0.005
  sim->particles().add({0.02, -0.006, 0.1}, {}, {}, kR, kM, 0);  // outside
  sim->initialize();
  Given c;
  c.probes.slab_thickness = 0.01;
  c.probes.slab_times = {0.0, 1.0};
  auto slab = probe(c, "slab");
  EXPECT_EQ(sample(*slab, *sim, 0.0).size(), 1u);
  EXPECT_EQ(sample(*slab, *sim, 0.5).size(), 0u);  // between snapshot times
  const auto r = sample(*slab, *sim, 1.2);         // the first sample after t = 1
  ASSERT_EQ(r.size(), 1u);
  EXPECT_DOUBLE_EQ(r[0][0], 1.2);
  EXPECT_DOUBLE_EQ(r[0][3], 0.01);
  EXPECT_EQ(sample(*slab, *sim, 2.0).size(), 0u);  // no more times
}

TEST(Probes, LevelIsEmptyWithNobodyOnTheAxis) {
  auto sim = empty_sim();
  sim->particles().add({0.1, 0, 0.1}, {}, {}, kR, kM, 0);
  sim->initialize();
  Given c;
  auto level = probe(c, "level");
  EXPECT_TRUE(std::isnan(sample(*level, *sim, 0.0)[0][1]));
}

}  // namespace
}  // namespace silodem
