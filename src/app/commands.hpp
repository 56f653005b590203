// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scenario/shear_cell.hpp"

namespace silodem::app {

struct RunOptions {
  std::string case_path;
  std::string out_dir;
  int threads = 0;
  std::vector<std::string> overrides;  // --set key=value
  bool report = true;                  // make figures and report.html at the end
  std::string resume_dir;              // --resume DIR: continue from DIR/checkpoint.bin
  bool force = false;                  // resume although DIR/case.toml changed
};

struct BenchOptions {
  std::string case_path;  // a silo case; main() defaults it to cases/paper/L3-I2.toml
  int threads = 0;
  long steps = 2000;
  bool json = false;
  std::vector<std::string> overrides;
  std::string cache_dir;   // default: $XDG_CACHE_HOME/silodem or ~/.cache/silodem
  bool refill = false;     // ignore a cached fill (and replace it)
  std::string export_dir;  // write the settled bed (bed.csv, bed.json) here for a peer code
  std::string from_dir;    // time the discharge of this run directory from its checkpoint
  double flowing = 0.0;    // also time the bed this many seconds into its discharge (cached)
};

struct StudyOptions {
  std::string study_path;
  std::string out_dir;
  int threads = 0;       // in all (0: every core)
  int jobs = 1;          // runs side by side, sharing the threads
  bool dry_run = false;  // check every run's case and list the runs; run nothing
  bool status = false;   // list the runs with their result or where they are; run nothing
};

struct CalibrateOptions {
  std::string case_path;
  std::vector<std::string> params;  // keys moved together
  std::string target;               // METRIC=VALUE
  std::string window;               // "T0,T1" (window_rate_kg_s)
  std::string bracket;              // "LO,HI"
  int seeds = 1;                    // seeds 1..N per evaluation
  double tolerance = 0.05;          // relative, on the metric
  int max_evaluations = 12;         // points after the bracket's two ends
  std::string out_dir;
  int threads = 0;
  int jobs = 1;
  std::vector<std::string> overrides;  // --set on every run
};

struct ShearTestOptions {
  std::string case_path;
  std::string out_dir;
  double preshear_kpa = 9.0;
  std::string normals;  // "7,6,5,4,3" (kPa); empty: the standard test's, scaled to the pre-shear
  std::string coal;     // one coal by name; empty: each coal of the case
  bool json = false;
  int threads = 0;
  std::uint64_t seed = 1;
  double width = kDefaultCellWidth, height = kDefaultCellHeight;  // mean CG diameters
  double inertial_number = 2e-3;
  double preshear_strain = 0.5, preshear_max_strain = 2.0, represhear_strain = 0.2,
         failure_strain = 0.25;
  std::string failure = "peak-ratio";  // the failure point of a shear: peak-ratio | peak-tau
  std::string refit;                  // a finished test's DIR: its series evaluated again (no case)
  bool failure_strain_given = false;  // --failure-strain on the command line
  bool preshear_max_strain_given = false;  // without it: the larger of 2 and --preshear-strain
  bool resume = false;                     // continue the test in out_dir from its checkpoint
  std::vector<std::string> overrides;
};

int run_command(const RunOptions& o);
int shear_test_command(const ShearTestOptions& o);
int default_threads();  // the cores this process may use
int study_command(const StudyOptions& o);
int calibrate_command(const CalibrateOptions& o);
int bench_command(const BenchOptions& o);
int check_command(const std::string& case_path, bool json,
                  const std::vector<std::string>& overrides);

// Figures and report.html of a run directory (tools/silodem_report.py). With
// quiet_if_unavailable, a missing Python/matplotlib is a warning, not an error.
int report_command(const std::string& dir, bool quiet_if_unavailable = false);
// Runs tools/<script> with the figure-making Python and `args`; returns its exit code (2 on a
// usage error). With quiet_if_unavailable, a missing Python/matplotlib is a warning (exit 0).
int run_tool(const std::string& script, const std::vector<std::string>& args,
             bool quiet_if_unavailable);
// Overlay figures of several runs into `out` (tools/silodem_compare.py); labels "A,B,...".
int compare_command(const std::vector<std::string>& dirs, const std::string& out,
                    const std::string& labels);

// Exit codes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInput = 2;          // bad case file or command line
inline constexpr int kExitSimulation = 3;     // the simulation went wrong
inline constexpr int kExitNotEmptied = 4;     // silo: the flow stopped (arching) or hit max_time
inline constexpr int kExitInterrupted = 130;  // SIGINT/SIGTERM: checkpoint written, resumable

}  // namespace silodem::app
