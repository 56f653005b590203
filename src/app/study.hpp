// SPDX-License-Identifier: MIT
// Pieces shared by `silodem study` and `silodem calibrate` (app-internal).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "app/run_jobs.hpp"
#include "io/run_metrics.hpp"

namespace silodem::app {

// A value as a --set item takes it: "key=value" with the value in TOML syntax.
std::string set_item(const std::string& key, const std::string& toml_value);
// A double in TOML syntax that reads back as the same double and stays a float ("1.0", not "1").
std::string toml_number(double x);
// A label made safe for a directory name (letters, digits, . + - kept; the rest '-').
std::string path_safe(const std::string& s);
// One progress line for a runner's status callback.
std::string runner_status(const char* what, std::size_t done, std::size_t total,
                          std::size_t running, double eta_s, double elapsed_s);
// A CSV cell of free text: quoted (quotes doubled) if it holds a comma, quote, space or newline.
std::string csv_text(const std::string& s);
// The metric columns of study.csv and calibration.csv, and a row of them for a run (empty cells
// for a run that is not finished).
std::vector<std::string> metric_columns();
std::vector<std::string> metric_cells(const RunMetrics* m, RunState state);
// Refuses (InputError naming `what`) a finished run directory whose case or overrides are not
// the ones planned for it now: a changed study must not mix old and new runs silently.
void check_run_matches(const RunJob& j, const char* what);

}  // namespace silodem::app
