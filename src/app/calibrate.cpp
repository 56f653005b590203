// SPDX-License-Identifier: MIT
// `silodem calibrate CASE --param KEY[,KEY...] --target METRIC=VALUE --out DIR`: finds the value
// of one parameter (several keys moved together) at which a run metric meets a target. A
// bracketing search (Illinois regula falsi where both ends flow, bisection where one arches)
// over seed-averaged evaluations; each evaluation's runs are kept under DIR/runs/, so the same
// command continues a killed search. Writes DIR/calibration.csv, DIR/calibration.json,
// DIR/calibration.png (tools/silodem_calibrate.py) and, if found, DIR/calibrated.toml.
#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <sstream>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/run_common.hpp"
#include "app/study.hpp"
#include "core/error.hpp"
#include "io/config/load.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

struct Evaluation {
  double x = 0;
  std::vector<RunJob> jobs;
  std::vector<RunState> states;
  std::vector<std::optional<RunMetrics>> metrics;
  std::vector<double> values;  // calibration_value per seed
  double mean = 0, se = 0;     // over the seeds; se = standard error of the mean
  bool arched = false;         // a seed's flow stopped
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string item; std::getline(in, item, sep);) v.push_back(item);
  return v;
}

std::pair<double, double> parse_pair(const std::string& s, const char* option, bool increasing) {
  const auto v = split(s, ',');
  try {
    if (v.size() == 2) {
      std::size_t n0 = 0, n1 = 0;
      const double a = std::stod(v[0], &n0), b = std::stod(v[1], &n1);
      if (n0 == v[0].size() && n1 == v[1].size() && std::isfinite(a) && std::isfinite(b) &&
          (!increasing || a < b))
        return {a, b};
    }
  } catch (const std::exception&) {
  }
  throw InputError(
      {}, option,
      fmt::format("'{}': expected two numbers A,B{}", s, increasing ? " with A < B" : ""));
}

}  // namespace

int calibrate_command(const CalibrateOptions& o) {
  // ---- the command line, checked before anything runs --------------------------------------
  const auto eq = o.target.find('=');
  if (eq == std::string::npos)
    throw InputError({}, "--target", fmt::format("'{}': expected METRIC=VALUE", o.target));
  const std::string metric = o.target.substr(0, eq);
  double target = 0;
  try {
    std::size_t n = 0;
    target = std::stod(o.target.substr(eq + 1), &n);
    if (n != o.target.size() - eq - 1 || !std::isfinite(target)) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw InputError({}, "--target", fmt::format("'{}': the value is not a number", o.target));
  }
  const auto& names = metric_names();
  if (std::find(names.begin(), names.end(), metric) == names.end() || metric == "wall_time_s") {
    std::string all;
    for (const auto& n : names)
      if (n != "wall_time_s") all += (all.empty() ? "" : ", ") + n;
    throw InputError({}, "--target", fmt::format("unknown metric '{}' (allowed: {})", metric, all));
  }
  double w0 = 0, w1 = 0;
  if (!o.window.empty()) std::tie(w0, w1) = parse_pair(o.window, "--window", true);
  if (metric == "window_rate_kg_s" && o.window.empty())
    throw InputError({}, "--window",
                     "window_rate_kg_s needs --window T0,T1 (s after the valve opens)");
  if (w0 < 0) throw InputError({}, "--window", "T0 must be >= 0 s");
  if (target == 0)
    throw InputError(
        {}, "--target",
        fmt::format("'{}': the tolerance is relative, so a target of 0 can only be met "
                    "exactly; calibrate against a value > 0",
                    o.target));
  if (!(o.tolerance > 0 && o.tolerance < 1))
    throw InputError({}, "--tolerance", fmt::format("{}: allowed 0 < REL < 1", o.tolerance));
  if (o.params.empty()) throw InputError({}, "--param", "give at least one case key");
  for (const auto& k : o.params)
    if (k.rfind("simulation.seed", 0) == 0)
      throw InputError({}, "--param", "the seeds are set by --seeds N (1..N)");
  for (const auto& item : o.overrides)
    if (item.rfind("simulation.seed", 0) == 0)
      throw InputError({}, "--set", "the seeds are set by --seeds N (1..N)");

  // The case with --set, as a table (for the current value and calibrated.toml) and checked.
  toml::table root;
  try {
    root = toml::parse_file(o.case_path);
  } catch (const toml::parse_error& e) {
    throw InputError({o.case_path, int(e.source().begin.line), int(e.source().begin.column)}, "",
                     std::string("TOML syntax error: ") + std::string(e.description()));
  }
  for (const auto& s : o.overrides) config::apply_override(root, s);
  double lo = 0, hi = 0;
  if (!o.bracket.empty()) {
    std::tie(lo, hi) = parse_pair(o.bracket, "--bracket", true);
  } else {
    const auto cur = root.at_path(o.params.front()).value<double>();
    if (!cur || !(*cur > 0))
      throw InputError({}, "--bracket",
                       fmt::format("not given, and {} has no positive value in the case to "
                                   "bracket (x/4 to 4x): give --bracket LO,HI",
                                   o.params.front()));
    lo = *cur / 4, hi = *cur * 4;
  }
  const std::string case_abs = fs::absolute(o.case_path).lexically_normal().string();
  auto overrides_at = [&](double x, int seed) {
    std::vector<std::string> v = o.overrides;
    for (const auto& k : o.params) v.push_back(set_item(k, toml_number(x)));
    v.push_back(set_item("simulation.seed", std::to_string(seed)));
    return v;
  };
  for (const double x : {lo, hi}) {
    const Case c = config::load_case_file(o.case_path, overrides_at(x, 1));
    if (!c.silo.present)
      throw InputError({o.case_path, 0, 0}, "CASE",
                       "calibrate needs a silo case (a [silo] section)");
  }

  const fs::path out(o.out_dir);
  // Evaluation jobs: the run directory of the value x with seed s.
  auto job_at = [&](double x, int seed) {
    RunJob j;
    j.name = fmt::format("x={}_seed={}", path_safe(toml_number(x)), seed);
    j.dir = out / "runs" / j.name;
    j.case_path = case_abs;
    j.overrides = overrides_at(x, seed);
    return j;
  };
  JobRunner::lock(out);
  // The first evaluations' runs hold another case (by content) or other --set values: refused
  // before search.txt and calibration.json are written, so they keep describing the search.
  for (const double x : {lo, hi})
    for (int s = 1; s <= o.seeds; ++s) check_run_matches(job_at(x, s), "calibration");
  {  // The same search only: another command line in this DIR would mix two searches. The case
     // is compared by content, run by run (check_run_matches), not by its path: a copy of the
     // case at another path (a frozen base) continues the search. search.txt records the path.
    std::string cmd;
    for (const auto& k : o.params) cmd += "param=" + k + "\n";
    cmd += fmt::format("target={}\nwindow={},{}\nbracket={},{}\nseeds={}\ntolerance={}\n", o.target,
                       w0, w1, toml_number(lo), toml_number(hi), o.seeds, o.tolerance);
    for (const auto& s : o.overrides) cmd += "set=" + s + "\n";
    const fs::path f = out / "search.txt";
    const std::string case_line = "case=" + case_abs + "\n";
    if (fs::exists(f)) {
      std::string old = read_text(f);
      if (old.rfind("case=", 0) == 0) old.erase(0, old.find('\n') + 1);
      if (old != cmd)
        throw InputError({}, "--out",
                         fmt::format("'{}' holds a search with other settings ({}); use a new "
                                     "--out DIR",
                                     out.string(), f.string()));
    }
    write_text(f, case_line + cmd);
  }
  const toml::table meta{{"case", case_abs},
                         {"params",
                          [&] {
                            toml::array a;
                            for (const auto& k : o.params) a.push_back(k);
                            return a;
                          }()},
                         {"metric", metric},
                         {"target", target},
                         {"tolerance", o.tolerance},
                         {"window_s", toml::array{w0, w1}},
                         {"bracket", toml::array{lo, hi}},
                         {"seeds", o.seeds}};
  write_text(out / "calibration.json", to_json(meta));

  // ---- evaluations ---------------------------------------------------------------------------
  JobRunner runner(o.threads, o.jobs, out / "logs", false);
  ProgressLine progress;
  std::vector<Evaluation> evals;
  auto write_csv = [&] {
    std::string text = "evaluation,x,seed,run,value,mean,standard_error";
    for (const auto& c : metric_columns()) text += "," + c;
    text += "\n";
    for (std::size_t e = 0; e < evals.size(); ++e) {
      const Evaluation& ev = evals[e];
      for (std::size_t s = 0; s < ev.jobs.size(); ++s) {
        auto num = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{}", v); };
        text +=
            fmt::format("{},{},{},{},{},{},{}", e, toml_number(ev.x), s + 1, ev.jobs[s].name,
                        s < ev.values.size() ? num(ev.values[s]) : "", num(ev.mean), num(ev.se));
        for (const auto& c : metric_cells(ev.metrics[s] ? &*ev.metrics[s] : nullptr, ev.states[s]))
          text += "," + c;
        text += "\n";
      }
    }
    write_text(out / "calibration.csv", text);
  };
  // Runs the evaluations at xs (their seeds side by side); false if interrupted.
  auto evaluate = [&](const std::vector<double>& xs) {
    std::vector<RunJob> jobs;
    const std::size_t first = evals.size();
    for (const double x : xs) {
      Evaluation ev;
      ev.x = x;
      for (int s = 1; s <= o.seeds; ++s) {
        const RunJob j = job_at(x, s);
        check_run_matches(j, "calibration");
        ev.jobs.push_back(j);
        jobs.push_back(j);
      }
      ev.states.assign(ev.jobs.size(), RunState::Absent);
      ev.metrics.resize(ev.jobs.size());
      evals.push_back(std::move(ev));
    }
    const auto outcomes = runner.run(
        jobs, [](std::size_t) {},
        [&](std::size_t done, std::size_t running, double eta) {
          progress.show(runner_status(fmt::format("calibrate, evaluation {}", first + 1).c_str(),
                                      done, jobs.size(), running, eta, progress.elapsed()));
        });
    progress.finish();
    if (runner.interrupted()) return false;
    for (std::size_t e = first, k = 0; e < evals.size(); ++e) {
      Evaluation& ev = evals[e];
      double sum = 0, sum2 = 0;
      for (std::size_t s = 0; s < ev.jobs.size(); ++s, ++k) {
        ev.states[s] = outcomes[k].state;
        if (ev.states[s] != RunState::Finished)
          throw SimulationError(fmt::format(
              "calibration run {} did not finish ({}; see {}): a guard stopped it, so the "
              "metric at x = {} is unknown",
              ev.jobs[s].name, to_string(ev.states[s]),
              (out / "logs" / (ev.jobs[s].name + ".log")).string(), toml_number(ev.x)));
        ev.metrics[s] = read_run_metrics(ev.jobs[s].dir, w0, w1);
        const double v = calibration_value(*ev.metrics[s], metric);
        ev.values.push_back(v);
        ev.arched = ev.arched || ev.metrics[s]->flow_stopped;
        sum += v, sum2 += v * v;
      }
      const double n = double(ev.values.size());
      ev.mean = sum / n;
      ev.se = n > 1 && std::isfinite(ev.mean)
                  ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1)) / n)
                  : 0.0;
      if (std::isinf(ev.mean)) ev.se = 0.0;
      fmt::print("  x = {:<12} {} = {:.6g}{}{}\n", toml_number(ev.x), metric, ev.mean,
                 ev.se > 0 ? fmt::format(" +- {:.2g}", ev.se) : "",
                 ev.arched ? "  (a seed arched: flow stopped)" : "");
      std::fflush(stdout);
    }
    write_csv();
    return true;
  };
  const double band = o.tolerance * std::fabs(target);
  // A point where a seed arched is never accepted: its mean mixes flowing and arched seeds (the
  // flow is bimodal there), and their spread would let almost any target pass.
  auto within = [&](const Evaluation& e) {
    return !e.arched && std::isfinite(e.mean) && std::fabs(e.mean - target) <= std::max(band, e.se);
  };
  auto finish_figure = [&] { run_tool("silodem_calibrate.py", {out.string()}, true); };

  fmt::print(
      "calibrate {} ({}) so that {} = {} (+-{:g}%), bracket [{}, {}], {} seed(s) per point\n",
      o.params.front(),
      o.params.size() > 1 ? fmt::format("{} keys together", o.params.size())
                          : std::string("one key"),
      metric, target, 100 * o.tolerance, toml_number(lo), toml_number(hi), o.seeds);
  std::fflush(stdout);
  if (!evaluate({lo, hi})) return kExitInterrupted;
  for (const auto& e : evals)
    if (std::isnan(e.mean))
      throw SimulationError(
          fmt::format("{} is undefined at x = {} (e.g. the silo emptied before "
                      "the window began): choose another window",
                      metric, toml_number(e.x)));
  std::size_t ilo = 0, ihi = 1;
  std::optional<std::size_t> found;
  std::string why;
  if (within(evals[0]))
    found = 0;
  else if (within(evals[1]))
    found = 1;
  else if ((evals[0].mean - target) * (evals[1].mean - target) > 0) {
    why = fmt::format(
        "the target is not bracketed: {} = {:.6g} at {} and {:.6g} at {}, both on "
        "one side of {}; widen --bracket",
        metric, evals[0].mean, toml_number(lo), evals[1].mean, toml_number(hi), target);
  }
  int side = 0;
  double glo = evals[ilo].mean - target, ghi = evals[ihi].mean - target;
  const double resolution = 0.1 * o.tolerance;
  for (int n = 0; !found && why.empty(); ++n) {
    const double a = evals[ilo].x, b = evals[ihi].x;
    if (b - a <= resolution * std::max(std::fabs(a), std::fabs(b))) {
      why = fmt::format(
          "no value meets the target: {} jumps from {:.6g} at {} to {:.6g} at {} "
          "(a bracket {:.2g}% wide): a cliff, not a smooth dependence",
          metric, evals[ilo].mean, toml_number(a), evals[ihi].mean, toml_number(b),
          100 * (b - a) / std::max(std::fabs(a), std::fabs(b)));
      break;
    }
    if (n >= o.max_evaluations) {
      why = fmt::format(
          "not found in {} evaluations (bracket now [{}, {}]); raise "
          "--max-evaluations or loosen --tolerance",
          o.max_evaluations, toml_number(a), toml_number(b));
      break;
    }
    double x = 0.5 * (a + b);
    const bool smooth =
        std::isfinite(glo) && std::isfinite(ghi) && !evals[ilo].arched && !evals[ihi].arched;
    if (smooth) {
      x = b - ghi * (b - a) / (ghi - glo);
      x = std::clamp(x, a + 0.1 * (b - a), b - 0.1 * (b - a));
    }
    if (!evaluate({x})) return kExitInterrupted;
    const std::size_t i = evals.size() - 1;
    const double g = evals[i].mean - target;
    if (std::isnan(g))
      throw SimulationError(fmt::format("{} is undefined at x = {}", metric, toml_number(x)));
    if (within(evals[i])) {
      found = i;
    } else if ((g > 0) == (glo > 0)) {
      ilo = i, glo = g;
      if (smooth && side == -1) ghi *= 0.5;  // Illinois: the end kept twice weighs half
      side = smooth ? -1 : 0;
    } else {
      ihi = i, ghi = g;
      if (smooth && side == 1) glo *= 0.5;
      side = smooth ? 1 : 0;
    }
  }
  write_csv();
  finish_figure();
  if (!found) {
    fmt::print(stderr, "calibrate: {}; every evaluation is in {}\n", why,
               (out / "calibration.csv").string());
    return kExitNotEmptied;
  }
  const Evaluation& e = evals[*found];
  toml::table cal = root;
  for (const auto& k : o.params) config::apply_override(cal, set_item(k, toml_number(e.x)));
  if (auto m = cal.at_path("output.measured").value<std::string>(); m && fs::path(*m).is_relative())
    config::apply_override(
        cal, set_item("output.measured", "\"" +
                                             (fs::absolute(fs::path(o.case_path).parent_path() / *m)
                                                  .lexically_normal()
                                                  .string()) +
                                             "\""));
  std::ostringstream text;
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::string keys;
  for (const auto& k : o.params) keys += (keys.empty() ? "" : ", ") + k;
  text << fmt::format(
      "# Calibrated by `silodem calibrate` on {}: {} = {} so that {} = {} (+-{:g}%, or the seeds' "
      "standard error);\n# measured there: {:.6g} +- {:.2g} over {} seed(s), after {} evaluations "
      "in the bracket [{}, {}].\n# Base case: {}{}. Every evaluation: {}.\n",
      date, keys, toml_number(e.x), metric, target, 100 * o.tolerance, e.mean, e.se, o.seeds,
      evals.size(), toml_number(lo), toml_number(hi), case_abs,
      o.overrides.empty() ? "" : fmt::format(" with {} --set value(s)", o.overrides.size()),
      (fs::absolute(out) / "calibration.csv").lexically_normal().string());
  text << cal << "\n";
  write_text(out / "calibrated.toml", text.str());
  fmt::print("calibrate: {} = {} gives {} = {:.6g} (target {}); wrote {}\n", keys, toml_number(e.x),
             metric, e.mean, target, (out / "calibrated.toml").string());
  return kExitOk;
}

}  // namespace silodem::app
