// SPDX-License-Identifier: MIT
// The virtual shear cell (issue 17) on frictionless, cohesionless spheres (three sizes, 1.6 to
// 2.4 mm). Such an assembly has no cohesion and a small but nonzero macroscopic friction, from
// geometry alone: tan(phi) = 0.10 in quasi-static steady shear (Peyneau & Roux, Phys. Rev. E 78,
// 011307, 2008). The test checks the steady pre-shear ratio tau / sigma against that within 0.05
// (a cell of about 300 spheres scatters: seeds 1-3 of this cell gave 0.110 to 0.143, mean 0.128;
// the rate adds a little, the mean was 0.15 at an inertial number of 5e-3), the locus's intercept
// against zero within 10% of the pre-shear stress, and that the servo held the pre-shear stress
// within 5%.
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <vector>

#include "io/config/load.hpp"
#include "scenario/shear_cell.hpp"

namespace silodem {
namespace {

TEST(ShearCell, FrictionlessSpheresHaveThePeyneauRouxFrictionAndNoCohesion) {
  const Case c =
      config::load_case_file(SILODEM_SOURCE_DIR "/tests/data/frictionless_spheres.toml", {});
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  ShearTestSpec spec;
  spec.preshear = 2e3;  // k / (sigma d) = 250: stiff grains
  spec.normals = {1.4e3, 0.8e3};
  spec.width = 6;
  spec.height = 6;
  spec.inertial_number = 1e-3;
  spec.preshear_strain = 0.4;
  // Every shear counts as steady, so the first pre-shear stops at its least strain, the first
  // check with two windows of 0.2 (this test reads it beyond 0.2), and not at the largest.
  spec.preshear_max_strain = 2.0;
  spec.steady_height_change = spec.steady_ratio_change = 1e9;
  spec.represhear_strain = 0.1;
  spec.failure_strain = 0.15;
  const ShearTestResult r = run_shear_test(c, report, model, 0, spec, {});
  // Steady shear: the first pre-shear beyond a strain of 0.2.
  double tau = 0, sigma = 0;
  for (const auto& row : r.series)
    if (row.phase == "preshear" && row.point == 0 && row.strain > 0.2)
      tau += row.tau, sigma += row.sigma;
  ASSERT_GT(sigma, 0.0);
  EXPECT_NEAR(tau / sigma, 0.10, 0.05);
  for (const auto& p : r.points) EXPECT_NEAR(p.preshear.sigma, spec.preshear, 0.05 * spec.preshear);
  EXPECT_NEAR(r.locus.cohesion, 0.0, 0.1 * spec.preshear);
  EXPECT_TRUE(r.preshear_steady);
  EXPECT_GE(r.preshear_strain, 0.4);
  EXPECT_LT(r.preshear_strain, 0.4 + 2 * spec.sample_strain);
  for (const auto& p : r.points) EXPECT_TRUE(p.preshear_steady);  // over the two halves
  EXPECT_GT(r.solid_fraction, 0.55);  // a dense random packing (0.64 for monodisperse spheres)
  EXPECT_LT(r.solid_fraction, 0.70);
}

}  // namespace
}  // namespace silodem

namespace silodem {
namespace {

// A checkpoint taken anywhere in the test and continued gives the test never interrupted, bit
// for bit: the same rows, failure points, locus and step count (one thread, so one summation
// order). The test is stopped six times, each time continued from the bytes the last stop
// wrote: early in the compression, near the end of the first pre-shear, between stages (the
// first pre-shear done, the bulk density's stage not begun), in the hold at the first normal
// stress after its pre-shear (servo on, its integral wound up), near the end of the last shear
// to failure, and at the very last chance (every stage done, only the fit left). The stops are
// placed by counting the test's checkpoint chances up to the progress line that ends each of
// those phases.
TEST(ShearCell, ResumesFromACheckpointBitForBit) {
  const Case c =
      config::load_case_file(SILODEM_SOURCE_DIR "/tests/data/frictionless_spheres.toml", {});
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  ShearTestSpec spec;
  spec.preshear = 2e3;
  spec.normals = {1.5e3, 1e3};
  spec.width = 5;
  spec.height = 4;
  spec.inertial_number = 1e-2;
  spec.preshear_strain = 0.1;
  spec.preshear_max_strain = 0.2;
  spec.represhear_strain = 0.05;
  spec.failure_strain = 0.05;
  spec.threads = 1;

  long chances = 0;
  ShearCheckpointing count;
  count.stop = [&] { return ++chances < 0; };
  std::vector<std::pair<std::string, long>> ends;  // each progress line and the chances before it
  const ShearTestResult whole = run_shear_test(
      c, report, model, 0, spec, [&](const std::string& m) { ends.emplace_back(m, chances); },
      &count);
  auto end_of = [&](const std::string& start) {
    for (const auto& [m, n] : ends)
      if (m.find(start) != std::string::npos) return n;
    ADD_FAILURE() << "no progress line containing '" << start << "'";
    return 0L;
  };
  const long first_preshear = end_of(": preshear 0 at"), preshear_1 = end_of(": preshear 1 at"),
             last_shear = end_of(": shear 2 at");
  // The chance after a shear's progress line is the tick between its stage and the next.
  const std::vector<long> stops = {
      3, first_preshear - 2, first_preshear + 1, preshear_1 + 3, last_shear - 2, chances};
  for (std::size_t k = 1; k < stops.size(); ++k) ASSERT_GT(stops[k], stops[k - 1]);

  std::vector<unsigned char> saved;
  long seen = 0, stop_at = 0;
  ShearCheckpointing ck;
  ck.stop = [&] { return ++seen == stop_at; };
  ck.write = [&](const std::function<void(ByteWriter&)>& state) {
    ByteWriter w;
    state(w);
    saved = w.bytes();
  };
  long done = 0;  // chances passed before the last stop
  for (long at : stops) {
    std::optional<ByteReader> from;
    if (!saved.empty()) from.emplace(saved);
    ck.resume = from ? &*from : nullptr;
    seen = 0;
    stop_at = at - done;
    EXPECT_THROW(run_shear_test(c, report, model, 0, spec, {}, &ck), ShearInterrupted);
    ASSERT_FALSE(saved.empty());
    if (from) {
      EXPECT_TRUE(from->done());  // the state was read to its end
    }
    done = at;
  }
  ByteReader last(saved);
  ck.resume = &last;
  seen = 0;
  stop_at = -1;
  const ShearTestResult resumed = run_shear_test(c, report, model, 0, spec, {}, &ck);
  EXPECT_EQ(seen, chances - done);  // it went on where the last stop was

  ASSERT_EQ(resumed.series.size(), whole.series.size());
  for (std::size_t i = 0; i < whole.series.size(); ++i) {
    const ShearSample &a = whole.series[i], &b = resumed.series[i];
    ASSERT_EQ(a.phase, b.phase) << "row " << i;
    ASSERT_EQ(a.point, b.point) << "row " << i;
    ASSERT_EQ(a.time, b.time) << "row " << i;
    ASSERT_EQ(a.strain, b.strain) << "row " << i;
    ASSERT_EQ(a.sigma, b.sigma) << "row " << i;
    ASSERT_EQ(a.tau, b.tau) << "row " << i;
    ASSERT_EQ(a.height, b.height) << "row " << i;
  }
  ASSERT_EQ(resumed.points.size(), whole.points.size());
  for (std::size_t k = 0; k < whole.points.size(); ++k) {
    EXPECT_EQ(resumed.points[k].sigma, whole.points[k].sigma);
    EXPECT_EQ(resumed.points[k].tau, whole.points[k].tau);
    EXPECT_EQ(resumed.points[k].preshear.tau, whole.points[k].preshear.tau);
  }
  EXPECT_EQ(resumed.locus.cohesion, whole.locus.cohesion);
  EXPECT_EQ(resumed.locus.friction_angle, whole.locus.friction_angle);
  EXPECT_EQ(resumed.bulk_density, whole.bulk_density);
  EXPECT_EQ(resumed.preshear_strain, whole.preshear_strain);
  EXPECT_EQ(resumed.glued, whole.glued);
  EXPECT_EQ(resumed.steps, whole.steps);
  EXPECT_EQ(resumed.warnings, whole.warnings);
}

// A checkpoint keeps a result whole: what load_shear_result reads is what save_shear_result
// wrote, every field, each given a value of its own so that two fields read in each other's
// place would show (a test of several coals keeps its finished ones so).
TEST(ShearCell, ResultRoundTripsThroughACheckpoint) {
  ShearTestResult r;
  r.coal = "Longwanggou";
  r.particles = 1234, r.glued = 321;
  r.width = 0.101, r.sheared_height = 0.082, r.mean_diameter = 0.0093, r.shear_velocity = 0.024;
  r.dt = 1.5e-5, r.bulk_density = 812.5, r.solid_fraction = 0.61;
  r.preshear = {9.01e3, 5.61e3};
  r.preshear_steady = true, r.preshear_strain = 1.6;
  r.points.push_back({7e3, 6.9e3, 5.3e3, 0.14, {8.98e3, 5.8e3}, true});
  r.points.push_back({3e3, 2.86e3, 2.56e3, 0.17, {8.93e3, 5.56e3}, false});
  YieldLocus& y = r.locus;
  y.cohesion = 671.0, y.friction_angle = 0.5857, y.rms_residual = 41.0;
  y.cohesion_stderr = 131.0, y.friction_angle_stderr = 0.017;
  y.unconfined = {1.21e3, 1.22e3}, y.consolidation = {15.3e3, 12.1e3};
  y.unconfined_yield = 2.44e3, y.major_consolidation = 27.4e3, y.flow_function = 11.2;
  y.consolidation_tangent = false;
  r.series.push_back({"preshear", 0, 0.48, 0.005, 8.9e3, 5.1e3, 0.167});
  r.series.push_back({"shear", 2, 9.97, 0.25, 5.9e3, 4.4e3, 0.171});
  r.steps = 123456789;
  r.warnings = {"one", "two"};
  ByteWriter w;
  save_shear_result(w, r);
  ByteReader in(w.bytes());
  const ShearTestResult o = load_shear_result(in);
  EXPECT_TRUE(in.done());
  EXPECT_EQ(o.coal, r.coal);
  EXPECT_EQ(o.particles, r.particles);
  EXPECT_EQ(o.glued, r.glued);
  EXPECT_EQ(o.width, r.width);
  EXPECT_EQ(o.sheared_height, r.sheared_height);
  EXPECT_EQ(o.mean_diameter, r.mean_diameter);
  EXPECT_EQ(o.shear_velocity, r.shear_velocity);
  EXPECT_EQ(o.dt, r.dt);
  EXPECT_EQ(o.bulk_density, r.bulk_density);
  EXPECT_EQ(o.solid_fraction, r.solid_fraction);
  EXPECT_EQ(o.preshear.sigma, r.preshear.sigma);
  EXPECT_EQ(o.preshear.tau, r.preshear.tau);
  EXPECT_EQ(o.preshear_steady, r.preshear_steady);
  EXPECT_EQ(o.preshear_strain, r.preshear_strain);
  ASSERT_EQ(o.points.size(), r.points.size());
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    EXPECT_EQ(o.points[k].sigma_target, r.points[k].sigma_target) << k;
    EXPECT_EQ(o.points[k].sigma, r.points[k].sigma) << k;
    EXPECT_EQ(o.points[k].tau, r.points[k].tau) << k;
    EXPECT_EQ(o.points[k].strain_at_peak, r.points[k].strain_at_peak) << k;
    EXPECT_EQ(o.points[k].preshear.sigma, r.points[k].preshear.sigma) << k;
    EXPECT_EQ(o.points[k].preshear.tau, r.points[k].preshear.tau) << k;
    EXPECT_EQ(o.points[k].preshear_steady, r.points[k].preshear_steady) << k;
  }
  EXPECT_EQ(o.locus.cohesion, y.cohesion);
  EXPECT_EQ(o.locus.friction_angle, y.friction_angle);
  EXPECT_EQ(o.locus.rms_residual, y.rms_residual);
  EXPECT_EQ(o.locus.cohesion_stderr, y.cohesion_stderr);
  EXPECT_EQ(o.locus.friction_angle_stderr, y.friction_angle_stderr);
  EXPECT_EQ(o.locus.unconfined.centre, y.unconfined.centre);
  EXPECT_EQ(o.locus.unconfined.radius, y.unconfined.radius);
  EXPECT_EQ(o.locus.consolidation.centre, y.consolidation.centre);
  EXPECT_EQ(o.locus.consolidation.radius, y.consolidation.radius);
  EXPECT_EQ(o.locus.unconfined_yield, y.unconfined_yield);
  EXPECT_EQ(o.locus.major_consolidation, y.major_consolidation);
  EXPECT_EQ(o.locus.flow_function, y.flow_function);
  EXPECT_EQ(o.locus.consolidation_tangent, y.consolidation_tangent);
  ASSERT_EQ(o.series.size(), r.series.size());
  for (std::size_t i = 0; i < r.series.size(); ++i) {
    EXPECT_EQ(o.series[i].phase, r.series[i].phase) << i;
    EXPECT_EQ(o.series[i].point, r.series[i].point) << i;
    EXPECT_EQ(o.series[i].time, r.series[i].time) << i;
    EXPECT_EQ(o.series[i].strain, r.series[i].strain) << i;
    EXPECT_EQ(o.series[i].sigma, r.series[i].sigma) << i;
    EXPECT_EQ(o.series[i].tau, r.series[i].tau) << i;
    EXPECT_EQ(o.series[i].height, r.series[i].height) << i;
  }
  EXPECT_EQ(o.steps, r.steps);
  EXPECT_EQ(o.warnings, r.warnings);
}

}  // namespace
}  // namespace silodem
