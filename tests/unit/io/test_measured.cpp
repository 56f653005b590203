// SPDX-License-Identifier: MIT
// Measured outlet data: the CSV reader's errors name file:line:column; the comparison with the
// simulated bins follows its stated rule (the bin holding t; empty or zero values skipped).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/measured.hpp"
#include "scenario/outlet_stats.hpp"

namespace silodem {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("silodem_measured_" + name);
  std::ofstream(p) << text;
  return p.string();
}

std::string error_of(const std::string& text) {
  const std::string p = write_file("bad.csv", text);
  try {
    load_measured_csv(p, {"case.toml", 7, 1});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Measured, ReadsRateAndCalorificWithGaps) {
  const std::string p =
      write_file("ok.csv", "t_s, rate_kg_s ,calorific_kcal_kg,note\n0.5,0.3,,a\n1.5,,4000,b\n\n");
  const MeasuredData m = load_measured_csv(p, {});
  ASSERT_EQ(m.t.size(), 2u);
  EXPECT_TRUE(m.has_rate && m.has_calorific);
  EXPECT_DOUBLE_EQ(m.rate[0], 0.3);
  EXPECT_TRUE(std::isnan(m.calorific[0]));
  EXPECT_TRUE(std::isnan(m.rate[1]));
  EXPECT_DOUBLE_EQ(m.calorific[1], 4000);
}

TEST(Measured, BadFilesNameTheLineAndColumn) {
  EXPECT_NE(error_of("time,rate\n1,2\n").find("must name t_s"), std::string::npos);
  const std::string e = error_of("t_s,rate_kg_s\n0.5,0.3\n1.0,abc\n");
  EXPECT_NE(e.find(":3:5"), std::string::npos) << e;
  EXPECT_NE(e.find("rate_kg_s = 'abc' is not a number"), std::string::npos) << e;
  EXPECT_NE(error_of("t_s,rate_kg_s\n1.0,0.3\n0.5,0.2\n").find("is not after"), std::string::npos);
  EXPECT_NE(error_of("t_s,rate_kg_s\n1.0,-0.3\n").find("out of range"), std::string::npos);
  EXPECT_NE(error_of("t_s,rate_kg_s\n").find("no data rows"), std::string::npos);
  try {
    load_measured_csv("/nonexistent/m.csv", {"case.toml", 7, 1});
    FAIL();
  } catch (const InputError& ex) {
    EXPECT_NE(std::string(ex.what()).find("case.toml:7:1"), std::string::npos) << ex.what();
  }
}

TEST(Measured, ErrorsAgainstTheBinHoldingEachTime) {
  std::vector<OutletBin> bins(3);
  for (int b = 0; b < 3; ++b) bins[b].t_start = b, bins[b].t_end = b + 1.0;
  bins[0].rate = 0.4, bins[0].calorific = 3000;
  bins[1].rate = 0.5, bins[1].calorific = std::nan("");  // nothing left in bin 1
  bins[2].rate = 0.3, bins[2].calorific = 4400;
  MeasuredData m;
  m.t = {0.5, 1.0, 2.9, 7.0};
  m.rate = {0.5, 0.4, 0.0, 1.0};  // |0.4-0.5|/0.5 = 0.2, |0.5-0.4|/0.4 = 0.25, zero skipped
  m.calorific = {3000, 3000, 4000, 4000};  // 0, empty bin skipped, 0.1; t = 7 outside
  const MeasuredErrors e = compare_with_measured(bins, m);
  EXPECT_EQ(e.rate_points, 2);
  EXPECT_NEAR(e.rate_max, 0.25, 1e-12);
  EXPECT_NEAR(e.rate_mean, 0.225, 1e-12);
  EXPECT_EQ(e.calorific_points, 2);
  EXPECT_NEAR(e.calorific_max, 0.1, 1e-12);
  EXPECT_NEAR(e.calorific_mean, 0.05, 1e-12);
}

}  // namespace
}  // namespace silodem
