// SPDX-License-Identifier: MIT
// The metrics a study or calibration reads from a run directory (issue 16): the windowed rate
// against hand-computed bin overlaps, the state of a run directory from its files, and the
// calibration convention for a stopped flow (rate 0, time infinite).
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/run_metrics.hpp"

namespace fs = std::filesystem;
using namespace silodem;

namespace {
// Bins of 0.1 s with 1, 2, 3, 4 g: 10, 20, 30, 40 g/s.
std::vector<OutletRow> bins() {
  return {{0.0, 0.1, 0.001}, {0.1, 0.2, 0.002}, {0.2, 0.3, 0.003}, {0.3, 0.4, 0.004}};
}

fs::path fresh_dir(const char* name) {
  // Unique per process: two build trees may run their tests at once.
  const fs::path d = fs::temp_directory_path() /
                     (std::string("silodem_metrics_") + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}
}  // namespace

TEST(RunMetrics, WindowRateIsTheOverlappingMassOverTheWindow) {
  // [0.15, 0.35]: half of bin 2 (1 g), all of bin 3 (3 g), half of bin 4 (2 g) = 6 g in 0.2 s.
  EXPECT_NEAR(window_rate(bins(), 0.15, 0.35, false, 0.4), 0.030, 1e-15);
  // Whole bins: [0.1, 0.3] holds 5 g in 0.2 s.
  EXPECT_NEAR(window_rate(bins(), 0.1, 0.3, false, 0.4), 0.025, 1e-15);
  // Past the last bin of a stopped flow nothing leaves: [0.3, 0.5] holds 4 g in 0.2 s.
  EXPECT_NEAR(window_rate(bins(), 0.3, 0.5, false, 0.4), 0.020, 1e-15);
  // An emptied silo is measured up to its last particle: [0.3, 0.5] -> [0.3, 0.4], 4 g in 0.1 s.
  EXPECT_NEAR(window_rate(bins(), 0.3, 0.5, true, 0.4), 0.040, 1e-15);
  // A window after an emptied silo's end has no rate.
  EXPECT_TRUE(std::isnan(window_rate(bins(), 0.5, 0.6, true, 0.4)));
}

TEST(RunMetrics, StateOfARunDirectory) {
  const fs::path d = fresh_dir("state");
  EXPECT_EQ(run_state(d / "none"), RunState::Absent);
  EXPECT_EQ(run_state(d), RunState::Absent);  // empty
  write(d / "summary.json", R"({"complete": false, "end": "running"})");
  EXPECT_EQ(run_state(d), RunState::Restart);  // killed in the fill
  write(d / "checkpoint.bin", "x");
  EXPECT_EQ(run_state(d), RunState::Resumable);
  write(d / "summary.json", R"({"complete": false, "end": "interrupted", "error": "signal 2"})");
  EXPECT_EQ(run_state(d), RunState::Resumable);  // an interruption is not a failure
  write(d / "summary.json",
        R"({"complete": false, "end": "error during the discharge", "error": "NaN"})");
  EXPECT_EQ(run_state(d), RunState::Failed);  // a guard: the last checkpoint stays, not redone
  // An output failure (a full disk) keeps its checkpoint: resumed once the cause is fixed.
  write(
      d / "summary.json",
      R"J({"complete": false, "end": "error during the discharge (output)", "error": "ENOSPC"})J");
  EXPECT_EQ(run_state(d), RunState::Resumable);
  write(d / "summary.json", R"({"complete": true, "end": "emptied", "error": ""})");
  EXPECT_EQ(run_state(d), RunState::Finished);
  fs::remove(d / "checkpoint.bin");
  write(d / "summary.json",
        R"({"complete": false, "end": "interrupted during the fill", "error": "signal 15"})");
  EXPECT_EQ(run_state(d), RunState::Restart);  // no checkpoint: the fill starts again
  write(d / "summary.json",
        R"({"complete": false, "end": "error during the fill", "error": "overlap guard"})");
  EXPECT_EQ(run_state(d), RunState::Failed);
  write(d / "summary.json", "[1, 2]");  // not an object: as if there were no summary
  EXPECT_EQ(run_state(d), RunState::Restart);
  fs::remove_all(d);
}

TEST(RunMetrics, ReadsSummaryAndOutletAndAStoppedFlowCountsAsNoFlow) {
  const fs::path d = fresh_dir("read");
  write(d / "summary.json",
        R"J({"complete": true, "end": "flow stopped (no outflow for stall_time)", "error": "",
            "flow_stopped": true, "filled_mass_kg": 0.02, "discharged_mass_kg": 0.01,
            "discharge_time_s": 0.4, "mean_rate_kg_s": 0.025, "particles_lost": 3,
            "outlet_mean_calorific_kcal_kg": 4000.5, "wall_time_s": 12, "k": 3
})J");
  write(d / "outlet.csv",
        "t_start_s,t_end_s,mass_kg,rate_kg_s,cumulative_kg,calorific_kcal_kg\n"
        "0,0.1,0.001,0.01,0.001,4000\n0.1,0.2,0.002,0.02,0.003,4000\n"
        "0.2,0.3,0.003,0.03,0.006,4000\n0.3,0.4,0.004,0.04,0.01,4000\n0.4,0.5,,,0.01,\n");
  const RunMetrics m = read_run_metrics(d, 0.2, 0.6);
  EXPECT_TRUE(m.complete);
  EXPECT_TRUE(m.flow_stopped);
  EXPECT_FALSE(m.emptied());
  EXPECT_EQ(m.particles_lost, 3);
  EXPECT_DOUBLE_EQ(metric_value(m, "discharged_fraction"), 0.5);
  EXPECT_NEAR(m.window_rate_kg_s, 0.007 / 0.4, 1e-15);  // bins 3 and 4, then nothing
  EXPECT_DOUBLE_EQ(metric_value(m, "mean_rate_kg_s"), 0.025);
  EXPECT_EQ(calibration_value(m, "mean_rate_kg_s"), 0.0);
  EXPECT_TRUE(std::isinf(calibration_value(m, "discharge_time_s")));
  EXPECT_NEAR(calibration_value(m, "window_rate_kg_s"), 0.007 / 0.4, 1e-15);
  EXPECT_THROW(metric_value(m, "rate"), std::invalid_argument);
  fs::remove_all(d);
}

TEST(RunMetrics, ATimeLimitEndsTheWindow) {
  // Stopped by max_time at 0.3 s: [0.2, 0.6] is measured over [0.2, 0.3] only (3 g in 0.1 s),
  // not as if nothing had left after the time limit.
  const fs::path d = fresh_dir("limit");
  write(d / "summary.json",
        R"({"complete": true, "end": "time limit", "error": "", "flow_stopped": false,
            "discharge_time_s": 0.29, "discharge_end_time_s": 0.3})");
  write(d / "outlet.csv", "t_start_s,t_end_s,mass_kg\n0,0.1,0.001\n0.1,0.2,0.002\n0.2,0.3,0.003\n");
  EXPECT_NEAR(read_run_metrics(d, 0.2, 0.6).window_rate_kg_s, 0.030, 1e-15);
  EXPECT_TRUE(std::isinf(calibration_value(read_run_metrics(d), "discharge_time_s")));
  fs::remove_all(d);
}

TEST(RunMetrics, OutletCsvIsReadByColumnNameAndABadCellNamesItsLine) {
  const fs::path d = fresh_dir("outlet");
  // Columns in another order, a blank mass (an empty bin) and a trailing column.
  write(d / "a.csv", "mass_kg,t_end_s,t_start_s,extra\n0.5,1,0,x\n,2,1,y\n0.25,3,2,z\n");
  const auto rows = read_outlet_csv(d / "a.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].t_start, 0.0);
  EXPECT_EQ(rows[0].t_end, 1.0);
  EXPECT_EQ(rows[0].mass, 0.5);
  EXPECT_EQ(rows[1].mass, 0.0);
  EXPECT_EQ(rows[2].mass, 0.25);
  // A cell that is not a number: the error names the file, line 3 and the column.
  write(d / "b.csv", "t_start_s,t_end_s,mass_kg\n0,1,0.5\n1,2x,0.5\n");
  try {
    read_outlet_csv(d / "b.csv");
    ADD_FAILURE() << "a bad cell was read";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("b.csv:3"), std::string::npos) << what;
    EXPECT_NE(what.find("t_end_s"), std::string::npos) << what;
  }
  // No mass column at all.
  write(d / "c.csv", "t_start_s,t_end_s\n0,1\n");
  EXPECT_THROW(read_outlet_csv(d / "c.csv"), std::runtime_error);
  fs::remove_all(d);
}
