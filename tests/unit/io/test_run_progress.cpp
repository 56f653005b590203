// SPDX-License-Identifier: MIT
// progress.json (io/run_progress.hpp): what a run writes comes back, an unknown ETA stays
// unknown, a damaged file is "no progress"; runs_eta, the wall time until a set of runs ends,
// against schedules worked by hand; and a run's own ETA: the windowed outflow rate of an
// intermittent flow, and discharge_eta against hand-worked cases.
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

// An intermittent flow: bursts of 0.5 s at 1 kg/s every 5 s, mean 0.1 kg/s, reported every 1 ms
// of simulated time as a discharge does. One 0.5 s outlet bin sees 1 kg/s or nothing, so an ETA
// built on it swings tenfold or is unknown; the 5 s window must give the mean. Any 5 s window
// holds exactly one burst (0.5 kg); the window's start may lie up to 0.05 s (window/100) before
// t - 5 s, which can add up to 0.05 kg over up to 5.05 s: 0.099-0.109 kg/s.
TEST(OutflowWindow, AnIntermittentFlowGivesItsMeanRate) {
  OutflowWindow w(5.0);
  double mass = 0.0;
  int checked = 0;
  for (int i = 1; i <= 30000; ++i) {
    const double t = 1e-3 * i;
    if (std::fmod(t, 5.0) < 0.5) mass += 1.0 * 1e-3;
    w.add(t, mass);
    if (t < 0.999) {
      EXPECT_TRUE(std::isnan(w.rate())) << "t = " << t;  // less than a fifth of the window
    } else if (t >= 1.001 && t < 5.06) {
      EXPECT_FALSE(std::isnan(w.rate())) << "t = " << t;  // a fifth of the window is enough
    } else if (t >= 5.06) {
      ASSERT_GE(w.rate(), 0.099) << "t = " << t;
      ASSERT_LE(w.rate(), 0.1095) << "t = " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 24000);
  // Between 1 s and 5 s the window is what there is, from the first pair (1 ms, 1 g out): a burst
  // of 0.5 kg in the first 0.5 s, then nothing, seen at 2 s.
  OutflowWindow v(5.0);
  for (int i = 1; i <= 2000; ++i) v.add(1e-3 * i, i <= 500 ? 1e-3 * i : 0.5);
  EXPECT_NEAR(v.rate(), (0.5 - 1e-3) / 1.999, 1e-9);
}

// A resumed run reports times from its checkpoint on; a time before the newest starts anew.
TEST(OutflowWindow, TimeGoingBackStartsAnew) {
  OutflowWindow w(5.0);
  for (int i = 1; i <= 6000; ++i) w.add(1e-3 * i, 2e-3 * i);  // 2 kg/s
  EXPECT_NEAR(w.rate(), 2.0, 1e-9);
  w.add(3.0, 0.0);
  EXPECT_TRUE(std::isnan(w.rate()));
  for (int i = 1; i <= 2000; ++i) w.add(3.0 + 1e-3 * i, 0.5e-3 * i);  // 0.5 kg/s
  EXPECT_NEAR(w.rate(), 0.5, 1e-9);
}

// cost 1e-3 wall s per particle and simulated s, 1000 particles, 10 kg to go at 1 kg/s: T_e = 10 s
// and the count falls linearly to none, so the wall time is 1e-3 x 1000 x 10 / 2 = 5 s. With 5 s
// of max_time left: 1 x 5 x (1 - 5 / 20) = 3.75 s.
TEST(DischargeEta, HandWorkedCases) {
  EXPECT_DOUBLE_EQ(discharge_eta(1e-3, 1000, 10, 1.0, 100), 5.0);
  EXPECT_DOUBLE_EQ(discharge_eta(1e-3, 1000, 10, 1.0, 5), 3.75);
  EXPECT_DOUBLE_EQ(discharge_eta(1e-3, 1000, 0, 1.0, 5), 0.0);       // nothing left to go
  EXPECT_DOUBLE_EQ(discharge_eta(1e-3, 1000, 10, 1.0, -1), 0.0);     // past max_time
  EXPECT_TRUE(std::isnan(discharge_eta(1e-3, 1000, 10, 0.0, 100)));  // no outflow
  EXPECT_TRUE(std::isnan(discharge_eta(0.0, 1000, 10, 1.0, 100)));   // no cost yet
  EXPECT_TRUE(std::isnan(discharge_eta(1e-3, 1000, 10, kNaN, 100)));
}

}  // namespace
