// SPDX-License-Identifier: MIT
// The yield locus fit and its Mohr circles against geometry: the fitted line through exact
// points, each circle tangent to the locus (centre-to-line distance = radius) and through its
// point (the origin; the pre-shear point), and f_c against Schulze's closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

TEST(YieldLocus, RefusesFewerThanTwoDistinctStresses) {
  EXPECT_THROW(fit_yield_locus({{3e3, 1e3}}, {9e3, 3e3}), std::invalid_argument);
  EXPECT_THROW(fit_yield_locus({{3e3, 1e3}, {3e3, 1.2e3}}, {9e3, 3e3}), std::invalid_argument);
}

}  // namespace
}  // namespace silodem
