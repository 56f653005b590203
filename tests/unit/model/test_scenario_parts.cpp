// SPDX-License-Identifier: MIT
// Scenario notation, Eq. 17 outlet statistics (T-U6), size sampling.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario/layers.hpp"
#include "scenario/outlet_stats.hpp"
#include "scenario/silo_geometry.hpp"
#include "scenario/size_distribution.hpp"

namespace silodem {
namespace {

TEST(Scenario, ParsesTopFirst) {
  const auto l = parse_scenario("L3-I2");
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].symbol, "L");
  EXPECT_EQ(l[0].segments, 3);
  EXPECT_EQ(segments_bottom_up(l), (std::vector<std::string>{"I", "I", "L", "L", "L"}));
  EXPECT_EQ(segments_bottom_up(parse_scenario("L2-I1")), (std::vector<std::string>{"I", "L", "L"}));
  EXPECT_EQ(segments_bottom_up(parse_scenario("I1-L4")),
            (std::vector<std::string>{"L", "L", "L", "L", "I"}));
}

TEST(Scenario, MalformedNamesAreRefusedWithAReason) {
  for (const char* bad :
       {"", "L", "3L", "L3-", "L3--I2", "L3I", "L0-I2", "L3+I2", "L2-L3", "L3 I2"}) {
    try {
      parse_scenario(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("expected coal symbols"), std::string::npos) << e.what();
    }
  }
}

TEST(OutletStats, TU6_CalorificValueEq17) {
  const std::vector<double> q = {4788, 3108};
  for (double x : {0.0, 0.25, 0.5, 1.0})
    EXPECT_NEAR(mixture_calorific({x, 1 - x}, q), 3108 + 1680 * x, 1e-9);
  // L3-I2 inventory at the measured bulk densities (VERIFICATION.md 1.5): 4632 kcal/kg.
  const SiloGeometry g;
  const double h = g.cone_height / 5;
  const double m_i = 728 * g.volume(0, 2 * h), m_l = 778 * g.volume(2 * h, 5 * h);
  EXPECT_NEAR(m_l, 28.46, 0.01);
  EXPECT_NEAR(m_i, 2.92, 0.01);
  EXPECT_NEAR(mixture_calorific({m_l, m_i}, q), 4632, 1.0);
}

TEST(OutletStats, BinsRatesFractionsAndCumulative) {
  std::vector<OutletRecord> out = {{0.2, 1, 1.0}, {0.7, 0, 3.0}, {1.5, 0, 2.0}, {2.9, 1, 0.5}};
  const auto b = outlet_bins(out, 1.0, 3.0, {4788, 3108});
  ASSERT_EQ(b.size(), 3u);
  EXPECT_DOUBLE_EQ(b[0].mass, 4.0);
  EXPECT_DOUBLE_EQ(b[0].rate, 4.0);
  EXPECT_DOUBLE_EQ(b[0].fraction[0], 0.75);
  EXPECT_NEAR(b[0].calorific, 0.75 * 4788 + 0.25 * 3108, 1e-9);
  EXPECT_DOUBLE_EQ(b[1].fraction[0], 1.0);
  EXPECT_DOUBLE_EQ(b[2].cumulative, 6.5);
  EXPECT_DOUBLE_EQ(b[2].calorific, 3108);
  const auto empty = outlet_bins({}, 1.0, 2.0, {4788, 3108});
  EXPECT_TRUE(std::isnan(empty[0].calorific));  // no mass, no calorific value
}

TEST(SizeDistribution, SamplesMassFractionsTimesK) {
  CoalProperties c;
  c.diameter = 2.8e-3;
  c.size_classes = {{1e-3, 0.5}, {2e-3, 0.5}};
  CoarseGraining cg;
  cg.k = 3;
  const SizeSampler s(c, cg);
  EXPECT_DOUBLE_EQ(s.max_diameter(), 6e-3);
  Random rng(11);
  double m_small = 0, m_large = 0;
  for (int i = 0; i < 200000; ++i) {
    const double d = s.sample(rng);
    (d < 4e-3 ? m_small : m_large) += d * d * d;
  }
  // Equal mass fractions: small spheres are 8x as many by number.
  EXPECT_NEAR(m_small / (m_small + m_large), 0.5, 0.01);
}

}  // namespace
}  // namespace silodem
