// SPDX-License-Identifier: MIT
// silodem: coarse-grained DEM of wet, cohesive coal discharging from a silo.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/config/schema.hpp"

int main(int argc, char** argv) {
  using namespace silodem;
  CLI::App cli{"silodem - coarse-grained DEM of wet coal discharging from silos"};
  cli.require_subcommand(1);

  app::RunOptions run;
  auto* run_cmd = cli.add_subcommand("run", "run a case and write its results into a directory");
  auto* case_opt =
      run_cmd->add_option("case", run.case_path, "case file (TOML)")->check(CLI::ExistingFile);
  auto* out_opt =
      run_cmd->add_option("--out", run.out_dir, "output directory (must not exist or be empty)");
  auto* resume_opt = run_cmd
                         ->add_option("--resume", run.resume_dir,
                                      "continue the interrupted silo run in this directory from "
                                      "its checkpoint (uses the case file in it)")
                         ->check(CLI::ExistingDirectory);
  run_cmd->add_flag("--force", run.force, "with --resume: resume although the case file changed");
  resume_opt->excludes(case_opt)->excludes(out_opt);
  case_opt->needs(out_opt);
  out_opt->needs(case_opt);
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: case file, else all)")
      ->check(CLI::Range(1, 1024));
  run_cmd->add_option("--set", run.overrides,
                      "override a case-file value, e.g. --set coarse_graining.k=4 (repeatable)");
  bool no_report = false;
  run_cmd->add_flag("--no-report", no_report, "do not make figures and report.html at the end");

  std::string check_path;
  bool json = false;
  auto* check_cmd = cli.add_subcommand("check", "validate a case and print the derived quantities");
  check_cmd->add_option("case", check_path, "case file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  check_cmd->add_flag("--json", json, "print one JSON object");
  std::vector<std::string> check_overrides;
  check_cmd->add_option("--set", check_overrides, "override a case-file value (repeatable)");

  std::string report_dir;
  auto* report_cmd =
      cli.add_subcommand("report", "make the figures (PNG) and report.html of a run directory");
  report_cmd->add_option("dir", report_dir, "run directory")
      ->required()
      ->check(CLI::ExistingDirectory);

  std::vector<std::string> compare_dirs;
  std::string compare_out, compare_labels;
  auto* compare_cmd = cli.add_subcommand(
      "compare", "overlay the outlet curves (rate, cumulative mass, calorific value) of runs");
  compare_cmd->add_option("dirs", compare_dirs, "run directories (two or more)")
      ->required()
      ->check(CLI::ExistingDirectory);
  compare_cmd
      ->add_option("--out", compare_out, "directory for the figures (must not exist or be empty)")
      ->required();
  compare_cmd->add_option("--labels", compare_labels, "legend labels, comma separated");

  app::BenchOptions bench;
  bench.case_path = SILODEM_CASES_DIR "/paper/L3-I2.toml";
  auto* bench_cmd = cli.add_subcommand(
      "bench", "time a settled silo bed and the start of its discharge (particle-steps/s, memory)");
  auto* bench_case =
      bench_cmd
          ->add_option("case", bench.case_path,
                       "silo case (default: the paper's L3-I2 at k = 3, cases/paper/L3-I2.toml)")
          ->check(CLI::ExistingFile);
  bench_cmd->add_option("--threads", bench.threads, "OpenMP threads (default: case file, else all)")
      ->check(CLI::Range(1, 1024));
  bench_cmd->add_option("--steps", bench.steps, "steps timed in each phase (default 2000)")
      ->check(CLI::Range(1L, 100000000L));
  bench_cmd->add_flag("--json", bench.json, "print one JSON object");
  bench_cmd->add_option("--set", bench.overrides, "override a case-file value (repeatable)");
  auto* bench_cache = bench_cmd->add_option("--cache", bench.cache_dir,
                                            "directory of cached fills (default ~/.cache/silodem)");
  auto* bench_refill =
      bench_cmd->add_flag("--refill", bench.refill, "fill again instead of loading a cached fill");
  auto* bench_export =
      bench_cmd->add_option("--export-bed", bench.export_dir,
                            "write the settled bed (bed.csv, bed.json) into this directory");
  bench_cmd
      ->add_option("--from", bench.from_dir,
                   "time --steps steps of this run directory's discharge from its checkpoint (a "
                   "flowing bed, its case as the directory holds it, --set applied on top; the "
                   "directory is not changed)")
      ->check(CLI::ExistingDirectory)
      ->excludes(bench_case)
      ->excludes(bench_cache)
      ->excludes(bench_refill)
      ->excludes(bench_export);

  auto* docs_cmd =
      cli.add_subcommand("config-docs", "print the case-file reference (docs/config.md)");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : app::kExitInput;
  }
  try {
    if (*run_cmd) {
      if (run.resume_dir.empty() && run.case_path.empty())
        throw InputError({}, "run", "give a case file and --out DIR, or --resume DIR");
      if (!run.overrides.empty() && !run.resume_dir.empty())
        throw InputError({}, "--set",
                         "a resumed run uses the case in its directory; --set is refused");
      run.report = !no_report;
      return app::run_command(run);
    }
    if (*report_cmd) return app::report_command(report_dir);
    if (*bench_cmd) return app::bench_command(bench);
    if (*compare_cmd) return app::compare_command(compare_dirs, compare_out, compare_labels);
    if (*check_cmd) return app::check_command(check_path, json, check_overrides);
    if (*docs_cmd) {
      fmt::print("{}", config::markdown());
      return 0;
    }
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return app::kExitInput;
  } catch (const SimulationError& e) {
    fmt::print(stderr, "simulation error: {}\n", e.what());
    return app::kExitSimulation;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
