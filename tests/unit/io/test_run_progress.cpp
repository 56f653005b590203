// SPDX-License-Identifier: MIT
// progress.json (io/run_progress.hpp): what a run writes comes back, an unknown ETA stays
// unknown, a damaged file is "no progress"; and runs_eta, the wall time until a set of runs ends,
// against schedules worked by hand.
#include <gtest/gtest.h>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>

#include "io/run_progress.hpp"

namespace fs = std::filesystem;
using namespace silodem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

fs::path fresh(const char* name) {
  const fs::path d = fs::temp_directory_path() /
                     (std::string("silodem_progress_") + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(RunProgress, RoundTripsAndIsRemoved) {
  const fs::path d = fresh("roundtrip");
  EXPECT_FALSE(read_run_progress(d).has_value());
  RunProgress p;
  p.phase = "discharge";
  p.t_s = 44.36, p.discharged_kg = 13.131, p.fraction = 0.418, p.rate_kg_s = 0.642;
  p.wall_s = 11677, p.eta_s = 2530;
  write_run_progress(d, p);
  const auto q = read_run_progress(d);
  ASSERT_TRUE(q.has_value());
  EXPECT_EQ(q->phase, "discharge");
  EXPECT_DOUBLE_EQ(q->t_s, 44.36);
  EXPECT_DOUBLE_EQ(q->discharged_kg, 13.131);
  EXPECT_DOUBLE_EQ(q->fraction, 0.418);
  EXPECT_DOUBLE_EQ(q->rate_kg_s, 0.642);
  EXPECT_DOUBLE_EQ(q->wall_s, 11677);
  EXPECT_DOUBLE_EQ(q->eta_s, 2530);
  // "2026-12-04T16:30:00Z": a UTC time stamp of 20 characters.
  ASSERT_EQ(q->updated.size(), 20u);
  EXPECT_EQ(q->updated[10], 'T');
  EXPECT_EQ(q->updated.back(), 'Z');
  remove_run_progress(d);
  fs::remove_all(d);
}

TEST(RunProgress, TheTimeStampIsUtcWhateverTheLocalZone) {
  // Written under a zone 5 h behind UTC, the stamp read back as UTC is now, not 5 h off.
  const fs::path d = fresh("utc");
  const char* old = std::getenv("TZ");
  const std::string saved = old ? old : "";
  setenv("TZ", "EST5", 1);
  tzset();
  RunProgress p;
  p.phase = "fill";
  const std::time_t before = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  write_run_progress(d, p);
  const std::time_t after = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  if (old)
    setenv("TZ", saved.c_str(), 1);
  else
    unsetenv("TZ");
  tzset();
  const auto q = read_run_progress(d);
  ASSERT_TRUE(q.has_value());
  std::tm tm{};
  ASSERT_NE(strptime(q->updated.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm), nullptr) << q->updated;
  const std::time_t stamped = timegm(&tm);
  EXPECT_GE(stamped, before) << q->updated;
  EXPECT_LE(stamped, after) << q->updated;
  remove_run_progress(d);
  EXPECT_FALSE(read_run_progress(d).has_value());
  remove_run_progress(d);  // removing what is not there is not an error
  fs::remove_all(d);
}

TEST(RunProgress, UnknownEtaStaysUnknownAndTheFillHasNoDischargeFields) {
  const fs::path d = fresh("fill");
  RunProgress p;
  p.phase = "fill";
  p.wall_s = 30;
  write_run_progress(d, p);
  const auto q = read_run_progress(d);
  ASSERT_TRUE(q.has_value());
  EXPECT_EQ(q->phase, "fill");
  EXPECT_TRUE(std::isnan(q->eta_s));
  EXPECT_TRUE(std::isnan(q->t_s));
  EXPECT_DOUBLE_EQ(q->wall_s, 30);
  fs::remove_all(d);
}

TEST(RunProgress, DamagedFileIsNoProgress) {
  const fs::path d = fresh("damaged");
  std::ofstream(d / "progress.json") << "{\"phase\": \"disch";
  EXPECT_FALSE(read_run_progress(d).has_value());
  std::ofstream(d / "progress.json") << "[1, 2]";
  EXPECT_FALSE(read_run_progress(d).has_value());
  fs::remove_all(d);
}

// Two slots. Running runs end in 100 s and 300 s; two pending runs of 200 s each start at 100 s
// (ends at 300 s) and at 300 s (ends at 500 s): 500 s.
TEST(RunsEta, ListSchedule) {
  EXPECT_DOUBLE_EQ(runs_eta({100, 300}, {0, 0}, 2, 200, 2), 500);
  // One slot: 100 + 3 x 50.
  EXPECT_DOUBLE_EQ(runs_eta({100}, {0}, 3, 50, 1), 250);
  // Free slots start pending runs at once: 2 runs of 200 s on 4 slots, nothing running.
  EXPECT_DOUBLE_EQ(runs_eta({}, {}, 2, 200, 4), 200);
  // Nothing left.
  EXPECT_DOUBLE_EQ(runs_eta({}, {}, 0, kNaN, 2), 0);
  // Only running runs, no mean needed: the last one to end.
  EXPECT_DOUBLE_EQ(runs_eta({40, 2530}, {0, 0}, 0, kNaN, 2), 2530);
}

TEST(RunsEta, UnknownsFallBackOrAreUnknown) {
  // A running run without an estimate counts as the mean less what it has run (at least 0).
  EXPECT_DOUBLE_EQ(runs_eta({kNaN, 100}, {150, 0}, 0, 400, 2), 250);
  EXPECT_DOUBLE_EQ(runs_eta({kNaN}, {900}, 0, 400, 1), 0);
  // Without a mean, an unknown running run or a pending one makes the answer unknown.
  EXPECT_EQ(runs_eta({kNaN, 100}, {150, 0}, 0, kNaN, 2), -1.0);
  EXPECT_EQ(runs_eta({100}, {0}, 1, kNaN, 2), -1.0);
}

}  // namespace
