// SPDX-License-Identifier: MIT
// The numbers a study or a calibration takes from a finished silo run directory: summary.json
// (read as JSON) and outlet.csv. Also the state of a run directory (not started, running or
// killed, resumable, finished), so that a study can skip, resume or restart each run.
#pragma once
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace silodem {

enum class RunState {
  Absent,     // no directory, or an empty one: start it
  Restart,    // started but killed before its first checkpoint (in the fill): start it again
  Resumable,  // checkpoint.bin and no final summary: `run --resume`
  Finished,   // summary.json complete (emptied, flow stopped or time limit)
  Failed,     // summary.json names an error (a guard stopped it): a result, not redone
};
const char* to_string(RunState s);

// What a study or calibration reads from a run directory's summary.json and outlet.csv.
struct RunMetrics {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  bool complete = false;
  bool flow_stopped = false;
  std::string end;    // summary.json's "end": "emptied", "flow stopped (...)", "time limit", ...
  std::string error;  // empty unless a guard stopped the run
  double filled_mass_kg = nan, discharged_mass_kg = nan, discharge_time_s = nan;
  double mean_rate_kg_s = nan;
  double window_rate_kg_s = nan;  // mass out in the window / its length (see window_rate)
  double outlet_mean_calorific_kcal_kg = nan, wall_time_s = nan;
  double k = nan;
  long particles_lost = 0;
  bool emptied() const { return end == "emptied"; }
};

// The state of a run directory (see RunState).
RunState run_state(const std::filesystem::path& dir);

// Reads summary.json and outlet.csv. `window` = {t0, t1} s after the valve opened (t1 > t0) sets
// window_rate_kg_s (for a run stopped by its time limit the window ends there); without one
// (t1 <= t0) it is NaN. Throws std::runtime_error naming the file
// if a file is missing or unreadable.
RunMetrics read_run_metrics(const std::filesystem::path& dir, double t0 = 0, double t1 = 0);

// One row of outlet.csv.
struct OutletRow {
  double t_start = 0, t_end = 0, mass = 0;
};
std::vector<OutletRow> read_outlet_csv(const std::filesystem::path& file);

// Mean outflow rate in [t0, t1] (s after the valve opened) from outlet bins: the mass of the
// bins' overlap with the window (a bin's mass spread evenly over it) divided by the window's
// length. A run that emptied before t1 is measured up to its discharge time (the silo had nothing
// left to give); a run that stopped flowing counts its zero outflow. NaN if the window starts
// after an emptied run's last particle.
double window_rate(const std::vector<OutletRow>& bins, double t0, double t1, bool emptied,
                   double discharge_time);

// The names of the metrics a study or calibration can use, and the value of one of them (a
// std::invalid_argument for an unknown name). For `calibration_value`, a run whose flow stopped
// did not empty: its mean rate counts 0 (its window rate already counts the zero outflow after
// the arch) and its discharge time, like that of any run that did not empty, is infinite.
const std::vector<std::string>& metric_names();
double metric_value(const RunMetrics& m, const std::string& name);
double calibration_value(const RunMetrics& m, const std::string& name);

}  // namespace silodem
