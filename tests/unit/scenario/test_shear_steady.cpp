// SPDX-License-Identifier: MIT
// The shear cell's steady-shear test (shear_is_steady) on series with a known answer: a sample
// compacting exponentially, h = h_inf (1 + A exp(-g / g0)), whose window means differ by
// h_inf A (g0 / w) (1 - exp(-w / g0))^2 exp(-(g - 2 w) / g0) at strain g (windows of w), and a
// mobilised friction rising linearly, whose windows differ by slope x w.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scenario/shear_cell.hpp"

namespace silodem {
namespace {

constexpr double kRow = 0.005;  // strain per row, ShearTestSpec's sample_strain

template <class Height, class Ratio>
std::vector<ShearSample> series(double strain, Height height, Ratio ratio) {
  std::vector<ShearSample> rows;
  for (int i = 1; i * kRow <= strain + 1e-12; ++i) {
    const double g = i * kRow, sigma = 9e3;
    rows.push_back({"preshear", 0, 0.0, g, sigma, ratio(g, i) * sigma, height(g, i)});
  }
  return rows;
}

TEST(ShearSteady, ACompactingSampleIsSteadyOnlyOnceItsHeightSettles) {
  const ShearTestSpec spec;  // windows of 0.2, height within 0.5%
  const double A = 0.10, g0 = 0.2, w = spec.steady_window, h_inf = 0.088;
  auto h = [&](double g, int) { return h_inf * (1.0 + A * std::exp(-g / g0)); };
  auto r = [](double, int) { return 0.45; };
  // Where the windows' difference falls to 0.5% of h_inf.
  const double q = 1.0 - std::exp(-w / g0);
  const double g_star = 2.0 * w - g0 * std::log(spec.steady_height_change / (A * g0 / w * q * q));
  ASSERT_NEAR(g_star, 0.816, 0.001);
  const auto per_window = std::size_t(std::lround(w / kRow));
  EXPECT_FALSE(shear_is_steady(series(0.5, h, r), per_window, spec));  // the old fixed strain
  EXPECT_FALSE(shear_is_steady(series(g_star - 0.03, h, r), per_window, spec));
  EXPECT_TRUE(shear_is_steady(series(g_star + 0.03, h, r), per_window, spec));
}

TEST(ShearSteady, ARisingFrictionIsNotSteady) {
  const ShearTestSpec spec;  // windows of 0.2, tau / sigma within 10% of the last window's
  const auto per_window = std::size_t(std::lround(spec.steady_window / kRow));
  auto h = [](double, int) { return 0.088; };
  // tau / sigma = 0.3 + 0.5 g: the windows differ by 0.1, 10% of the last window's mean
  // 0.3 + 0.5 (g - 0.1) once g = 1.5.
  auto r = [](double g, int) { return 0.3 + 0.5 * g; };
  EXPECT_FALSE(shear_is_steady(series(1.4, h, r), per_window, spec));
  EXPECT_TRUE(shear_is_steady(series(1.6, h, r), per_window, spec));
}

TEST(ShearSteady, SwingsAboutASteadyStateAreSteady) {
  const ShearTestSpec spec;
  const auto per_window = std::size_t(std::lround(spec.steady_window / kRow));
  // Swings of 20% in tau / sigma and 1% in height, row to row, with a period that does not
  // divide the window: the windows' means still agree within a few tenths of that.
  auto h = [](double, int i) { return 0.088 * (1.0 + 0.01 * std::sin(0.7 * i)); };
  auto r = [](double, int i) { return 0.45 * (1.0 + 0.2 * std::sin(1.3 * i)); };
  EXPECT_TRUE(shear_is_steady(series(0.6, h, r), per_window, spec));
  // A step in height between the windows is not.
  auto step = [](double g, int) { return g > 0.4 ? 0.087 : 0.088; };
  EXPECT_FALSE(shear_is_steady(series(0.6, step, r), per_window, spec));
}

TEST(ShearSteady, TooFewRowsAreNotSteady) {
  const ShearTestSpec spec;
  auto h = [](double, int) { return 0.088; };
  auto r = [](double, int) { return 0.45; };
  const auto rows = series(0.395, h, r);  // 79 rows: fewer than two windows of 40
  EXPECT_FALSE(shear_is_steady(rows, 40, spec));
  EXPECT_TRUE(shear_is_steady(rows, 39, spec));
  EXPECT_FALSE(shear_is_steady(rows, 0, spec));
}

TEST(ShearSteady, TheLargestStrainMayNotBeBelowTheLeast) {
  ShearTestSpec spec;
  spec.preshear_strain = 0.5;
  spec.preshear_max_strain = 0.4;
  try {
    check_shear_spec(spec);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--preshear-max-strain"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.4"), std::string::npos) << e.what();
  }
  spec.preshear_max_strain = 0.5;  // a fixed strain, the procedure before 2026-12-07
  EXPECT_NO_THROW(check_shear_spec(spec));
}

}  // namespace
}  // namespace silodem
