// SPDX-License-Identifier: MIT
// Runs many silo runs as child `silodem run` processes, several side by side, each into its own
// run directory: a finished run is skipped, a killed one resumed from its checkpoint (or started
// again if it was killed before its first checkpoint, early in its fill). The children die with the
// parent (PR_SET_PDEATHSIG), and a lock on the parent's directory keeps two runners out of it, so a
// killed study or calibration continues where it was when the same command is given again.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "io/run_metrics.hpp"

namespace silodem::app {

struct RunJob {
  std::string name;                    // for logs and the progress line
  std::filesystem::path dir;           // the run directory
  std::string case_path;               // the base case file
  std::vector<std::string> overrides;  // --set items
};

struct JobOutcome {
  RunState state = RunState::Absent;  // after the runner: Finished, Failed or still unfinished
  int exit_code = -1;                 // of the child (-1: not run now, it was already done)
};

class JobRunner {
 public:
  // `threads` in all, shared by `jobs` children (each gets max(1, threads / jobs)); logs go to
  // log_dir/<name>.log; `reports`: let each run make its figures and report.html.
  JobRunner(int threads, int jobs, std::filesystem::path log_dir, bool reports);
  ~JobRunner();
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // Takes a lock on `dir` (DIR/.lock), refusing with an InputError if another process holds it.
  static void lock(const std::filesystem::path& dir);
  // Whether another process holds that lock now (a study or calibration is running in `dir`).
  static bool locked(const std::filesystem::path& dir);

  // Runs the jobs that are not finished, at most `jobs` at a time. `on_done(i)` is called after
  // job i ends (or at once if it was already finished). `status(done, running, eta_s)` is called
  // about every second for a progress line; eta_s (-1: unknown) comes from runs_eta, with each
  // running run's own estimate from its progress.json and the mean wall time of the runs
  // finished here (before any has, of the running runs' estimated totals). Returns the outcomes;
  // stops early (children sent SIGTERM, so they checkpoint) if SIGINT or SIGTERM arrives: then
  // interrupted() is true. A child that exits 2 (bad input) ends the runner with an InputError.
  std::vector<JobOutcome> run(
      const std::vector<RunJob>& jobs, const std::function<void(std::size_t)>& on_done,
      const std::function<void(std::size_t done, std::size_t running, double eta_s)>& status);

  bool interrupted() const;
  int threads_per_job() const { return per_job_; }

 private:
  int jobs_, per_job_;
  std::filesystem::path log_dir_;
  bool reports_;
};

}  // namespace silodem::app
