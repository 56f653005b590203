// SPDX-License-Identifier: MIT
// The yield locus fit and its Mohr circles against geometry: the fitted line through exact
// points, each circle tangent to the locus (centre-to-line distance = radius) and through its
// point (the origin; the pre-shear point), and f_c against Schulze's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "scenario/yield_locus.hpp"

namespace silodem {
namespace {

double distance_to_locus(const YieldLocus& y, double m) {  // from (m, 0) to tau = C + sigma t
  const double t = std::tan(y.friction_angle);
  return std::abs(t * m - 0.0 + y.cohesion) / std::sqrt(1 + t * t);
}

TEST(YieldLocus, ExactPointsGiveTheLineAndTangentCircles) {
  // tau = 1 kPa + 0.6 sigma at 3..7 kPa; pre-shear at 9 kPa, on the locus's end (Jenike)
  std::vector<StressPoint> pts;
  for (double s : {3e3, 4e3, 5e3, 6e3, 7e3}) pts.push_back({s, 1e3 + 0.6 * s});
  const StressPoint pre{9e3, 0.95 * (1e3 + 0.6 * 9e3)};
  const YieldLocus y = fit_yield_locus(pts, pre);
  EXPECT_NEAR(y.cohesion, 1e3, 1e-8);
  EXPECT_NEAR(std::tan(y.friction_angle), 0.6, 1e-12);
  EXPECT_LT(y.rms_residual, 1e-8);
  // Unconfined circle: through the origin, tangent.
  EXPECT_NEAR(y.unconfined.centre, y.unconfined.radius, 1e-9);
  EXPECT_NEAR(distance_to_locus(y, y.unconfined.centre), y.unconfined.radius, 1e-6);
  // Schulze, Powders and Bulk Solids (2nd ed. 2021), ch. 3, for a linear locus:
  // f_c = 2 C cos(phi) / (1 - sin(phi)).
  const double phi = std::atan(0.6);
  EXPECT_NEAR(y.unconfined_yield, 2e3 * std::cos(phi) / (1 - std::sin(phi)), 1e-6);
  // Consolidation circle: through the pre-shear point, tangent, larger than the point's sigma.
  const MohrCircle& c = y.consolidation;
  EXPECT_TRUE(y.consolidation_tangent);
  EXPECT_NEAR(std::hypot(pre.sigma - c.centre, pre.tau), c.radius, 1e-6);
  EXPECT_NEAR(distance_to_locus(y, c.centre), c.radius, 1e-6);
  EXPECT_GT(y.major_consolidation, pre.sigma);
  EXPECT_NEAR(y.flow_function, y.major_consolidation / y.unconfined_yield, 1e-12);
}

TEST(YieldLocus, NoCohesionMeansNoUnconfinedStrengthAndAnInfiniteFlowFunction) {
  const YieldLocus y = fit_yield_locus({{3e3, 1.5e3}, {6e3, 3e3}}, {9e3, 4e3});
  EXPECT_NEAR(y.cohesion, 0.0, 1e-9);
  EXPECT_EQ(y.unconfined_yield, 0.0);
  EXPECT_EQ(y.flow_function, std::numeric_limits<double>::infinity());
  // Cohesionless: the consolidation circle's radius is centre x sin(phi).
  EXPECT_NEAR(y.consolidation.radius, y.consolidation.centre * std::sin(y.friction_angle), 1e-6);
}

TEST(YieldLocus, StandardErrorsOfTheFitFollowTheTextbookFormulas) {
  // Points off the line tau = 1 kPa + 0.5 sigma at 3..7 kPa by d x (1, -2, 0, 2, -1): the
  // residuals sum to zero and are orthogonal to sigma, so least squares returns the line itself,
  // SSE = 10 d^2 and s^2 = SSE / (n - 2) = 10 d^2 / 3. With mean(sigma) = 5 kPa and Sxx = 10 kPa^2
  // (any regression text, e.g. Montgomery, Peck & Vining, Introduction to Linear Regression
  // Analysis, 5th ed., 2.3.2): se(C) = s sqrt(1/5 + 25/10) = s sqrt(2.7) = 3 d exactly, and
  // se(b) = s / sqrt(Sxx) = d sqrt(1/3) / kPa; phi = atan(b), so se(phi) = se(b) / (1 + b^2).
  const double d = 100.0;  // Pa
  const double e[] = {1, -2, 0, 2, -1};
  std::vector<StressPoint> pts;
  for (int i = 0; i < 5; ++i) {
    const double s = (3 + i) * 1e3;
    pts.push_back({s, 1e3 + 0.5 * s + e[i] * d});
  }
  const YieldLocus y = fit_yield_locus(pts, {9e3, 5e3});
  EXPECT_NEAR(y.cohesion, 1e3, 1e-8);
  EXPECT_NEAR(std::tan(y.friction_angle), 0.5, 1e-12);
  EXPECT_NEAR(y.cohesion_stderr, 3 * d, 1e-9);
  EXPECT_NEAR(y.friction_angle_stderr, d * std::sqrt(1.0 / 3.0) / 1e3 / 1.25, 1e-12);
  // The scatter about the line, not its level: the same residuals at 10x tell 10x the error.
  for (int i = 0; i < 5; ++i) pts[i].tau += 9 * e[i] * d;
  EXPECT_NEAR(fit_yield_locus(pts, {9e3, 5e3}).cohesion_stderr, 30 * d, 1e-8);
  // Two points leave no degree of freedom: no error estimate.
  const YieldLocus two = fit_yield_locus({{3e3, 2e3}, {6e3, 4e3}}, {9e3, 5e3});
  EXPECT_TRUE(std::isnan(two.cohesion_stderr));
  EXPECT_TRUE(std::isnan(two.friction_angle_stderr));
}

TEST(YieldLocus, RefusesFewerThanTwoDistinctStresses) {
  EXPECT_THROW(fit_yield_locus({{3e3, 1e3}}, {9e3, 3e3}), std::invalid_argument);
  EXPECT_THROW(fit_yield_locus({{3e3, 1e3}, {3e3, 1.2e3}}, {9e3, 3e3}), std::invalid_argument);
}

// A shear whose normal stress swings (the small cell's servo, yield_locus.hpp): the material
// holds tau / sigma = 0.40 at its peak (rows 10-12) and 0.30 elsewhere, and one swing at rows
// 4-6 doubles sigma. The largest shear stress is the swing's (PeakTau); the largest mobilised
// friction is the peak's (PeakRatio). Each gives its three-row window's mean.
TEST(FailurePick, PeakRatioFindsTheMaterialPeakAndPeakTauTheLargestSwing) {
  std::vector<StressPoint> rows(20, StressPoint{5e3, 0.30 * 5e3});
  for (int i : {4, 5, 6}) rows[std::size_t(i)] = {10e3, 0.30 * 10e3};
  for (int i : {10, 11, 12}) rows[std::size_t(i)] = {5e3, 0.40 * 5e3};
  const FailurePick tau = pick_failure(rows, FailureCriterion::PeakTau);
  EXPECT_EQ(tau.row, 5u);
  EXPECT_NEAR(tau.point.sigma, 10e3, 1e-9);
  EXPECT_NEAR(tau.point.tau, 3e3, 1e-9);
  const FailurePick ratio = pick_failure(rows, FailureCriterion::PeakRatio);
  EXPECT_EQ(ratio.row, 11u);
  EXPECT_NEAR(ratio.point.sigma, 5e3, 1e-9);
  EXPECT_NEAR(ratio.point.tau, 2e3, 1e-9);
  // A window at the ends has two rows: the mean of rows 0-1.
  std::vector<StressPoint> rising{{4e3, 2e3}, {6e3, 2e3}, {5e3, 1e3}, {5e3, 1e3}};
  const FailurePick first = pick_failure(rising, FailureCriterion::PeakRatio);
  EXPECT_EQ(first.row, 0u);
  EXPECT_NEAR(first.point.sigma, 5e3, 1e-9);
  EXPECT_NEAR(first.point.tau, 2e3, 1e-9);
  EXPECT_STREQ(failure_criterion_name(FailureCriterion::PeakRatio), "peak-ratio");
  EXPECT_STREQ(failure_criterion_name(FailureCriterion::PeakTau), "peak-tau");
}

// A row that is not a number (NaN) spoils the windows it is in, which are skipped, not picked
// and not blocking later ones; a shear whose normal stress is never positive has no tau / sigma
// peak, which is an error, not a point at row 0.
TEST(FailurePick, SkipsWindowsWithoutAFiniteKeyAndRefusesWhenNoneIsLeft) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<StressPoint> rows{{nan, nan}, {5e3, 1e3}, {5e3, 1e3}, {5e3, 2e3}, {5e3, 1e3}};
  for (auto c : {FailureCriterion::PeakTau, FailureCriterion::PeakRatio}) {
    const FailurePick p = pick_failure(rows, c);
    EXPECT_EQ(p.row, 4u);  // rows 3-4: tau 1.5 kPa, the largest finite window
    EXPECT_NEAR(p.point.tau, 1.5e3, 1e-9);
  }
  const std::vector<StressPoint> lifted{{0, 0}, {0, 0}, {-1e2, 0}};
  EXPECT_THROW(pick_failure(lifted, FailureCriterion::PeakRatio), std::invalid_argument);
  EXPECT_THROW(pick_failure({}, FailureCriterion::PeakTau), std::invalid_argument);
}

}  // namespace
}  // namespace silodem
