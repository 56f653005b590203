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
  // Bad input is one line, as every other error: without CLI11's "Run with --help" line.
  cli.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("error: ") + e.what() + "\n";
  });
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
  auto* bench_flowing =
      bench_cmd
          ->add_option("--flowing", bench.flowing,
                       "also discharge the bed to this time (s after the valve opens; cached "
                       "like the fill) and time --steps steps of the flowing bed there")
          ->check(CLI::Range(0.0, 1e6));
  bench_cmd
      ->add_option("--from", bench.from_dir,
                   "time --steps steps of this run directory's discharge from its checkpoint (a "
                   "flowing bed, its case as the directory holds it, --set applied on top; the "
                   "directory is not changed)")
      ->check(CLI::ExistingDirectory)
      ->excludes(bench_case)
      ->excludes(bench_cache)
      ->excludes(bench_refill)
      ->excludes(bench_export)
      ->excludes(bench_flowing);

  app::StudyOptions study;
  auto* study_cmd = cli.add_subcommand(
      "study",
      "run a case over a grid of case-key values and seeds; collect study.csv, figures "
      "and report.html (the same command continues a killed study)");
  study_cmd->add_option("study", study.study_path, "study file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  study_cmd->add_option("--out", study.out_dir, "study directory (created; reused to continue)")
      ->required();
  study_cmd->add_option("--threads", study.threads, "OpenMP threads in all (default: all cores)")
      ->check(CLI::Range(0, 1024));
  study_cmd->add_flag("--dry-run", study.dry_run,
                      "check every run's case and list the runs with their --set values; run "
                      "nothing, write nothing");
  study_cmd->add_flag("--status", study.status,
                      "list the runs: a finished one with its result, an unfinished one with "
                      "where it is (its progress.json); run nothing, write nothing");
  study_cmd->add_option("--jobs", study.jobs, "runs side by side, sharing the threads (default 1)")
      ->check(CLI::Range(1, 256));

  app::CalibrateOptions cal;
  std::string cal_params;
  auto* cal_cmd = cli.add_subcommand(
      "calibrate",
      "find the parameter value at which a run metric meets a target (bracketing "
      "search over seed-averaged runs; resumable)");
  cal_cmd->add_option("case", cal.case_path, "silo case file (TOML)")
      ->required()
      ->check(CLI::ExistingFile);
  cal_cmd->add_option("--param", cal_params, "case key(s) moved together, comma separated")
      ->required();
  cal_cmd->add_option("--target", cal.target, "METRIC=VALUE, e.g. mean_rate_kg_s=0.335")
      ->required();
  cal_cmd->add_option("--window", cal.window, "T0,T1: s after the valve opens (window_rate_kg_s)");
  cal_cmd->add_option("--bracket", cal.bracket, "LO,HI (default: the case's value / 4 and x 4)");
  cal_cmd->add_option("--seeds", cal.seeds, "seeds per evaluation, 1..N (default 1)")
      ->check(CLI::Range(1, 100));
  cal_cmd->add_option("--tolerance", cal.tolerance,
                      "relative tolerance on the metric (default 0.05)");
  cal_cmd
      ->add_option("--max-evaluations", cal.max_evaluations,
                   "evaluations after the bracket's ends (default 12)")
      ->check(CLI::Range(1, 1000));
  cal_cmd->add_option("--out", cal.out_dir, "directory of the search (created; reused to continue)")
      ->required();
  cal_cmd->add_option("--threads", cal.threads, "OpenMP threads in all (default: all cores)")
      ->check(CLI::Range(0, 1024));
  cal_cmd->add_option("--jobs", cal.jobs, "runs side by side (default 1)")
      ->check(CLI::Range(1, 256));
  cal_cmd->add_option("--set", cal.overrides,
                      "override a case-file value on every run (repeatable)");

  app::ShearTestOptions shear;
  auto* shear_cmd = cli.add_subcommand(
      "shear-test",
      "the FT-4 shear test (ASTM D7891) on each coal of a case with its contact model: yield "
      "locus, C, phi, f_c, sigma_1, ffc, bulk density");
  shear_cmd->add_option("case", shear.case_path, "case file (TOML); none with --refit")
      ->check(CLI::ExistingFile);
  shear_cmd->add_option("--out", shear.out_dir, "output directory (new or empty)")->required();
  auto* resume_flag = shear_cmd->add_flag(
      "--resume", shear.resume,
      "continue the interrupted test in --out from its shear_checkpoint.bin (give the same case "
      "and options)");
  shear_cmd->add_option("--preshear", shear.preshear_kpa,
                        "pre-shear normal stress, kPa (default 9)");
  shear_cmd->add_option("--normal", shear.normals,
                        "normal stresses of the failure points, kPa, comma separated (default "
                        "7,6,5,4,3 at 9 kPa; scaled with --preshear)");
  shear_cmd->add_option("--coal", shear.coal, "test only this coal (default: each)");
  shear_cmd->add_flag("--json", shear.json, "print the results as JSON on stdout");
  shear_cmd->add_option("--threads", shear.threads, "OpenMP threads (default: the case's)")
      ->check(CLI::Range(0, 1024));
  shear_cmd->add_option("--seed", shear.seed, "seed of the sample (default 1)");
  shear_cmd
      ->add_option("--width", shear.width,
                   fmt::format("cell side, mean CG diameters (default {:g})", kDefaultCellWidth))
      ->check(CLI::Range(2.0, 1000.0));
  shear_cmd
      ->add_option("--height", shear.height,
                   fmt::format("sheared sample height, mean CG diameters (default {:g})",
                               kDefaultCellHeight))
      ->check(CLI::Range(2.0, 1000.0));
  shear_cmd
      ->add_option("--inertial-number", shear.inertial_number,
                   "shear rate as the inertial number at the lowest stress (default 2e-3)")
      ->check(CLI::Range(1e-6, 0.1));
  shear_cmd
      ->add_option("--preshear-strain", shear.preshear_strain,
                   "least strain of the first pre-shear (default 0.5)")
      ->check(CLI::Range(0.01, 10.0));
  shear_cmd
      ->add_option("--preshear-max-strain", shear.preshear_max_strain,
                   "the first pre-shear goes on until steady, at most to this strain (default "
                   "2, or --preshear-strain if larger; equal to --preshear-strain: a fixed "
                   "strain, as before 2026-12-07)")
      ->check(CLI::Range(0.01, 20.0));
  shear_cmd
      ->add_option("--represhear-strain", shear.represhear_strain,
                   "strain of each later pre-shear (default 0.2)")
      ->check(CLI::Range(0.01, 10.0));
  shear_cmd
      ->add_option("--failure-strain", shear.failure_strain,
                   "strain of each shear to failure (default 0.25)")
      ->check(CLI::Range(0.01, 10.0));
  shear_cmd
      ->add_option("--failure", shear.failure,
                   "failure point of each shear: peak-ratio (largest tau / sigma, default) or "
                   "peak-tau (largest tau, before 2026-12-05)")
      ->check(CLI::IsMember({"peak-ratio", "peak-tau"}));
  auto* set_opt =
      shear_cmd->add_option("--set", shear.overrides, "override a case-file value (repeatable)");
  auto* refit_opt =
      shear_cmd
          ->add_option("--refit", shear.refit,
                       "evaluate a finished shear test's DIR again from its series (with "
                       "--failure): failure points, yield locus and figure, written to --out; "
                       "no case, no run")
          ->check(CLI::ExistingDirectory);
  // What a refit cannot change: the test was run with its own values of these.
  for (const char* name :
       {"--preshear", "--normal", "--coal", "--threads", "--seed", "--width", "--height",
        "--inertial-number", "--preshear-strain", "--preshear-max-strain", "--represhear-strain"})
    refit_opt->excludes(shear_cmd->get_option(name));
  refit_opt->excludes(set_opt);
  refit_opt->excludes(resume_flag);

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
    if (*study_cmd) {
      if (study.threads == 0) study.threads = app::default_threads();
      return app::study_command(study);
    }
    if (*cal_cmd) {
      for (std::size_t a = 0, b = 0; a <= cal_params.size(); a = b + 1) {
        b = cal_params.find(',', a);
        if (b == std::string::npos) b = cal_params.size();
        if (b > a) cal.params.push_back(cal_params.substr(a, b - a));
      }
      if (cal.threads == 0) cal.threads = app::default_threads();
      return app::calibrate_command(cal);
    }
    if (*shear_cmd) {
      shear.failure_strain_given = shear_cmd->count("--failure-strain") > 0;
      shear.preshear_max_strain_given = shear_cmd->count("--preshear-max-strain") > 0;
      return app::shear_test_command(shear);
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
