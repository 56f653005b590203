// SPDX-License-Identifier: MIT
// progress.json in a run directory (docs/runs.md): where an unfinished `silodem run` is. The run
// rewrites it every few seconds of wall time (atomically) and removes it when it ends with a
// result, so it exists only while the run is running or interrupted. A study or a calibration
// reads it to estimate its end before any of its runs has finished; a person or a script can
// read it too.
#pragma once
#include <deque>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace silodem {

struct RunProgress {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::string phase;           // "fill" or "discharge"
  double t_s = nan;            // simulated s after the valve opened (discharge only)
  double discharged_kg = nan;  // discharge only
  double fraction = nan;       // of the filled mass (discharge only)
  double rate_kg_s = nan;      // the recent outflow rate (discharge only)
  double wall_s = nan;         // wall time the run has used, over all its sessions
  double eta_s = nan;          // wall time to its end, NaN if unknown
  std::string updated;         // UTC time of writing, ISO 8601 (set by write_run_progress)
};

void write_run_progress(const std::filesystem::path& dir, RunProgress p);
// nullopt if the file is absent or not a progress object (never throws: it is advisory).
std::optional<RunProgress> read_run_progress(const std::filesystem::path& dir);
void remove_run_progress(const std::filesystem::path& dir);

// The wall time until a set of runs ends, `slots` at a time: the running ones end after
// `running_left` s each (NaN: unknown), and each pending one, started in the first free slot,
// takes `mean_run` s (NaN: unknown). A running one whose time is unknown counts as
// `mean_run` - `running_elapsed` (at least 0). Returns -1 if the answer needs an unknown.
double runs_eta(const std::vector<double>& running_left, const std::vector<double>& running_elapsed,
                std::size_t pending, double mean_run, int slots);

// The outflow rate over the last `window` simulated seconds, from the (t, mass out) pairs a
// discharge reports. An ETA needs this, not one outlet bin's rate: an intermittent flow's bins
// swing between a burst and nothing, and the ETA with them by orders of magnitude. NaN until
// the pairs span a fifth of the window (after a start or a resume).
class OutflowWindow {
 public:
  explicit OutflowWindow(double window_s = 5.0) : window_(window_s) {}
  void add(double t, double mass_out);
  double rate() const;

 private:
  double window_;
  std::deque<std::pair<double, double>> s_;  // (t, mass out), about window/100 apart
};

// The wall time to the end of a discharge: `to_go` kg still to leave at `rate` kg/s empties the
// silo in T_e = to_go / rate simulated s; the particles fall about linearly from `n` to none over
// it, so at `cost` wall s per particle and simulated s the part T = min(T_e, time_left) costs
// cost n T (1 - T / (2 T_e)). NaN if rate or cost is not positive.
double discharge_eta(double cost, double n, double to_go, double rate, double time_left);

}  // namespace silodem
