// SPDX-License-Identifier: MIT
// `silodem study STUDY.toml --out DIR`: runs a base case over a grid (cartesian product or zip)
// of case-key values and seeds, each as a normal run directory under DIR/runs/, and collects the
// metrics into DIR/study.csv, DIR/figures/ and DIR/report.html (tools/silodem_study.py). The
// same command continues a killed study: finished runs are skipped, interrupted ones resumed.
#include "app/study.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/run_common.hpp"
#include "core/error.hpp"
#include "io/config/load.hpp"
#include "io/run_progress.hpp"

namespace fs = std::filesystem;

namespace silodem::app {

std::string set_item(const std::string& key, const std::string& toml_value) {
  return key + "=" + toml_value;
}

std::string toml_number(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: inf, nan
  return s;
}

std::string path_safe(const std::string& s) {
  std::string out;
  for (char ch : s) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                    (ch >= '0' && ch <= '9') || ch == '.' || ch == '+' || ch == '-';
    out += ok ? ch : '-';
  }
  return out;
}

std::string runner_status(const char* what, std::size_t done, std::size_t total,
                          std::size_t running, double eta_s, double elapsed_s) {
  return fmt::format("{}: {}/{} runs done, {} running, wall {:.0f} s, ETA {}", what, done, total,
                     running, elapsed_s, eta_s >= 0 ? fmt::format("{:.0f} s", eta_s) : "?");
}

std::vector<std::string> metric_columns() {
  return {"state",
          "end",
          "flow_stopped",
          "filled_mass_kg",
          "discharged_mass_kg",
          "discharged_fraction",
          "discharge_time_s",
          "mean_rate_kg_s",
          "window_rate_kg_s",
          "outlet_mean_calorific_kcal_kg",
          "particles_lost",
          "wall_time_s"};
}

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n\r ") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::vector<std::string> metric_cells(const RunMetrics* m, RunState state) {
  auto num = [](double x) { return std::isfinite(x) ? fmt::format("{}", x) : std::string(); };
  if (!m) {
    std::vector<std::string> cells(metric_columns().size());
    cells[0] = state == RunState::Failed ? "failed" : "pending";
    return cells;
  }
  return {to_string(state),
          csv_text(m->end),
          m->flow_stopped ? "true" : "false",
          num(m->filled_mass_kg),
          num(m->discharged_mass_kg),
          num(metric_value(*m, "discharged_fraction")),
          num(m->discharge_time_s),
          num(m->mean_rate_kg_s),
          num(m->window_rate_kg_s),
          num(m->outlet_mean_calorific_kcal_kg),
          fmt::format("{}", m->particles_lost),
          num(m->wall_time_s)};
}

namespace {

// Two case texts hold the same case when they parse to the same TOML values: a comment or layout
// edit of a base case does not make the runs already made from it another case's.
bool same_case(const std::string& a, const std::string& b) {
  if (a == b) return true;
  try {
    return toml::parse(a) == toml::parse(b);
  } catch (const toml::parse_error&) {
    return false;
  }
}

}  // namespace

void check_run_matches(const RunJob& j, const char* what) {
  const RunDir dir(j.dir);
  if (!fs::exists(dir.case_file())) return;  // not started: nothing to mix up
  if (!same_case(read_text(dir.case_file()), read_text(j.case_path)) ||
      dir.overrides() != j.overrides)
    throw InputError({}, what,
                     fmt::format("run directory '{}' holds another case or other --set values "
                                 "than this {} plans for it (its base case or fixed settings "
                                 "changed); use a new --out DIR",
                                 j.dir.string(), what));
}

namespace {

// One varied dimension: labels[i] names the i-th variant, sets[i] its --set items.
struct Vary {
  std::string name;
  std::vector<std::string> labels;
  std::vector<std::vector<std::string>> sets;
  bool numeric = true;
};

struct Study {
  std::string title, base;
  std::vector<std::int64_t> seeds;
  std::vector<std::string> fixed;  // set = [...] on every run
  double window_t0 = 0, window_t1 = 0;
  bool run_reports = false;
  bool zip = false;
  std::vector<Vary> vary;
};

SourcePlace place_of(const std::string& file, const toml::node& n) {
  return {file, int(n.source().begin.line), int(n.source().begin.column)};
}

// Refuses a key of `t` that is present with another type than `type` (a wrong type must not be
// ignored: `seeds = 3` would otherwise run seed 1 only). `type`: string, bool, array, table,
// "array of strings".
void expect_type(const std::string& file, const toml::table& t, const char* key,
                 const std::string& type, const std::string& shown_key = {}) {
  const toml::node* n = t.get(key);
  if (!n) return;
  bool ok = type == "string"  ? n->is_string()
            : type == "bool"  ? n->is_boolean()
            : type == "array" ? n->is_array()
            : type == "table" ? n->is_table()
                              : n->is_array();
  if (ok && type == "array of strings")
    for (const auto& x : *n->as_array()) ok = ok && x.is_string();
  if (!ok)
    throw InputError(place_of(file, *n), shown_key.empty() ? key : shown_key,
                     fmt::format("must be {} {}", type == "array" ? "an" : "a", type));
}

// simulation.seed comes from seeds = [...]: a seed set elsewhere would be overridden silently.
void refuse_seed_key(const SourcePlace& place, const std::string& item, const char* where) {
  if (item.rfind("simulation.seed", 0) == 0)
    throw InputError(place, where,
                     fmt::format("'{}': the seed of each run comes from seeds = [...]", item));
}

// A value in TOML syntax (for --set) and as a label.
std::pair<std::string, std::string> value_text(const std::string& file, const toml::node& n,
                                               const std::string& key, bool& numeric) {
  if (const auto* i = n.as_integer())
    return {fmt::format("{}", i->get()), fmt::format("{}", i->get())};
  if (const auto* d = n.as_floating_point()) return {toml_number(d->get()), toml_number(d->get())};
  numeric = false;
  if (const auto* b = n.as_boolean())
    return {b->get() ? "true" : "false", b->get() ? "true" : "false"};
  if (const auto* s = n.as_string()) {
    std::string q = "\"";
    for (char ch : s->get()) {
      if (ch == '"' || ch == '\\') q += '\\';
      q += ch;
    }
    return {q + "\"", s->get()};
  }
  throw InputError(place_of(file, n), key,
                   "a value must be a number, a string or a boolean (for tables or several "
                   "keys that change differently, use labels = [...] with sets = [[...], ...])");
}

Study load_study(const std::string& file) {
  toml::table t;
  try {
    t = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    const auto& s = e.source();
    throw InputError({file, int(s.begin.line), int(s.begin.column)}, "",
                     std::string("TOML syntax error: ") + std::string(e.description()));
  }
  const SourcePlace top{file, 0, 0};
  static const std::vector<std::string> known = {"title",  "base",    "seeds",       "set",
                                                 "window", "combine", "run_reports", "vary"};
  for (const auto& [k, v] : t)
    if (std::find(known.begin(), known.end(), std::string(k.str())) == known.end())
      throw InputError(place_of(file, v), std::string(k.str()),
                       "unknown key (allowed: title, base, seeds, set, window, combine, "
                       "run_reports, [[vary]])");
  expect_type(file, t, "title", "string");
  expect_type(file, t, "base", "string");
  expect_type(file, t, "seeds", "array");
  expect_type(file, t, "set", "array of strings");
  expect_type(file, t, "window", "array");
  expect_type(file, t, "combine", "string");
  expect_type(file, t, "run_reports", "bool");
  expect_type(file, t, "vary", "array");
  Study s;
  s.title = t["title"].value_or(std::string());
  const auto base = t["base"].value<std::string>();
  if (!base)
    throw InputError(top, "base", "missing: the base case file, relative to the study file");
  const fs::path bp =
      fs::path(*base).is_absolute() ? fs::path(*base) : fs::path(file).parent_path() / *base;
  if (!fs::is_regular_file(bp))
    throw InputError(
        place_of(file, *t.get("base")), "base",
        fmt::format("'{}': no such case file ({} from the study file)", *base, bp.string()));
  s.base = fs::absolute(bp).lexically_normal().string();
  if (const auto* a = t["seeds"].as_array()) {
    for (const auto& n : *a) {
      const auto v = n.value<std::int64_t>();
      if (!v || *v < 0)
        throw InputError(place_of(file, n), "seeds", "each seed must be an integer >= 0");
      s.seeds.push_back(*v);
    }
  }
  if (s.seeds.empty()) s.seeds = {1};
  for (std::size_t i = 1; i < s.seeds.size(); ++i)
    if (std::find(s.seeds.begin(), s.seeds.begin() + long(i), s.seeds[i]) !=
        s.seeds.begin() + long(i))
      throw InputError(place_of(file, *t.get("seeds")), "seeds",
                       fmt::format("seed {} is listed twice", s.seeds[i]));
  if (const auto* a = t["set"].as_array()) {
    for (const auto& n : *a) {
      const auto v = n.value<std::string>();
      if (!v || v->find('=') == std::string::npos)
        throw InputError(place_of(file, n), "set", "each item must be a string \"key=value\"");
      refuse_seed_key(place_of(file, n), *v, "set");
      s.fixed.push_back(*v);
    }
  }
  if (const auto* a = t["window"].as_array()) {
    const auto t0 = a->size() == 2 ? (*a)[0].value<double>() : std::nullopt;
    const auto t1 = a->size() == 2 ? (*a)[1].value<double>() : std::nullopt;
    if (!t0 || !t1 || *t0 < 0 || *t1 <= *t0)
      throw InputError(place_of(file, *a), "window",
                       "expected [t0, t1] in s after the valve opens, 0 <= t0 < t1");
    s.window_t0 = *t0, s.window_t1 = *t1;
  }
  const std::string combine = t["combine"].value_or(std::string("product"));
  if (combine != "product" && combine != "zip")
    throw InputError(t.get("combine") ? place_of(file, *t.get("combine")) : top, "combine",
                     fmt::format("'{}': allowed \"product\" (every combination) or \"zip\" (the "
                                 "i-th value of each together)",
                                 combine));
  s.zip = combine == "zip";
  s.run_reports = t["run_reports"].value_or(false);
  const toml::array* va = t["vary"].as_array();
  if (!va || va->empty())
    throw InputError(top, "vary", "missing: at least one [[vary]] table (key + values)");
  for (const auto& n : *va) {
    const toml::table* vt = n.as_table();
    if (!vt) throw InputError(place_of(file, n), "vary", "each [[vary]] must be a table");
    const SourcePlace here = place_of(file, n);
    expect_type(file, *vt, "key", "string", "vary.key");
    expect_type(file, *vt, "keys", "array of strings", "vary.keys");
    expect_type(file, *vt, "values", "array", "vary.values");
    expect_type(file, *vt, "name", "string", "vary.name");
    expect_type(file, *vt, "labels", "array of strings", "vary.labels");
    expect_type(file, *vt, "sets", "array", "vary.sets");
    Vary v;
    std::vector<std::string> keys;
    if (const auto k = (*vt)["key"].value<std::string>()) keys.push_back(*k);
    if (const auto* ka = (*vt)["keys"].as_array())
      for (const auto& k : *ka)
        if (const auto ks = k.value<std::string>()) keys.push_back(*ks);
    for (const auto& k : keys) refuse_seed_key(here, k, "vary.key");
    for (const auto& [k, x] : *vt) {
      const std::string ks(k.str());
      if (ks != "key" && ks != "keys" && ks != "values" && ks != "name" && ks != "labels" &&
          ks != "sets")
        throw InputError(place_of(file, x), "vary." + ks,
                         "unknown key (allowed: name, key or keys with values, or labels with "
                         "sets)");
    }
    if (const auto* vals = (*vt)["values"].as_array()) {
      if (keys.empty())
        throw InputError(here, "vary.values", "values need key = \"...\" or keys = [...]");
      for (const auto& x : *vals) {
        const auto [text, label] = value_text(file, x, "vary.values", v.numeric);
        std::vector<std::string> items;
        for (const auto& k : keys) items.push_back(set_item(k, text));
        v.labels.push_back(label);
        v.sets.push_back(items);
      }
      const std::string& k0 = keys.front();
      v.name = (*vt)["name"].value_or(
          k0.substr(k0.rfind('.') == std::string::npos ? 0 : k0.rfind('.') + 1));
    } else if (const auto* labels = (*vt)["labels"].as_array()) {
      const auto* sets = (*vt)["sets"].as_array();
      if (!sets || sets->size() != labels->size())
        throw InputError(
            here, "vary.sets",
            "labels = [...] needs sets = [[\"key=value\", ...], ...] of the same length");
      v.numeric = false;
      for (std::size_t i = 0; i < labels->size(); ++i) {
        const auto label = (*labels)[i].value<std::string>();
        const auto* items = (*sets)[i].as_array();
        if (!label || !items)
          throw InputError(place_of(file, (*labels)[i]), "vary.labels",
                           "each label a string, each set a list of \"key=value\" strings");
        std::vector<std::string> its;
        for (const auto& it : *items) {
          const auto s2 = it.value<std::string>();
          if (!s2 || s2->find('=') == std::string::npos)
            throw InputError(place_of(file, it), "vary.sets",
                             "each item must be a string \"key=value\"");
          refuse_seed_key(place_of(file, it), *s2, "vary.sets");
          its.push_back(*s2);
        }
        v.labels.push_back(*label);
        v.sets.push_back(its);
      }
      const auto name = (*vt)["name"].value<std::string>();
      if (!name) throw InputError(here, "vary.name", "labels + sets need a name = \"...\"");
      v.name = *name;
    } else {
      throw InputError(here, "vary", "needs values = [...] (with key or keys) or labels + sets");
    }
    if (v.labels.empty()) throw InputError(here, "vary." + v.name, "no values");
    const auto cols = metric_columns();
    if (path_safe(v.name) != v.name || v.name == "seed" || v.name == "run" ||
        std::find(cols.begin(), cols.end(), v.name) != cols.end())
      throw InputError(here, "vary.name",
                       fmt::format("'{}': a name of letters, digits, '.', '+', '-', other than "
                                   "seed, run and the metric columns of study.csv; give name = "
                                   "\"...\"",
                                   v.name));
    for (const auto& w : s.vary)
      if (w.name == v.name)
        throw InputError(
            here, "vary.name",
            fmt::format("'{}' names two [[vary]] tables; give each its own name", v.name));
    s.vary.push_back(std::move(v));
  }
  if (s.zip)
    for (const auto& v : s.vary)
      if (v.labels.size() != s.vary.front().labels.size())
        throw InputError(top, "combine",
                         fmt::format("\"zip\" needs lists of one length: '{}' has {}, '{}' has {}",
                                     s.vary.front().name, s.vary.front().labels.size(), v.name,
                                     v.labels.size()));
  return s;
}

// Each point of the grid: the index into each Vary's variants.
std::vector<std::vector<std::size_t>> grid(const Study& s) {
  std::vector<std::vector<std::size_t>> pts;
  if (s.zip) {
    for (std::size_t i = 0; i < s.vary.front().labels.size(); ++i)
      pts.push_back(std::vector<std::size_t>(s.vary.size(), i));
    return pts;
  }
  pts.push_back({});
  for (const auto& v : s.vary) {
    std::vector<std::vector<std::size_t>> next;
    for (const auto& p : pts)
      for (std::size_t i = 0; i < v.labels.size(); ++i) {
        next.push_back(p);
        next.back().push_back(i);
      }
    pts = std::move(next);
  }
  return pts;
}

// True if DIR/progress.json was written within the last minute (a running run rewrites it every
// few seconds).
bool progress_is_fresh(const fs::path& dir) {
  std::error_code ec;
  const auto t = fs::last_write_time(dir / "progress.json", ec);
  return !ec && fs::file_time_type::clock::now() - t < std::chrono::seconds(60);
}

// `study --status`: each run's state, with its result (summary.json) or where it is
// (progress.json), and whether a study is running in `out` now.
void print_status(const std::vector<RunJob>& jobs, const fs::path& out, double t0, double t1) {
  std::size_t width = 0, finished = 0;
  for (const auto& j : jobs) width = std::max(width, j.name.size());
  const bool busy = JobRunner::locked(out);
  for (const auto& j : jobs) {
    const RunState st = run_state(j.dir);
    // An unfinished run of a running study whose progress.json is fresh is running now.
    const std::string state =
        busy && (st == RunState::Resumable || st == RunState::Restart) && progress_is_fresh(j.dir)
            ? "running"
            : to_string(st);
    std::string what;
    try {
      check_run_matches(j, "study");
    } catch (const InputError&) {
      // The study file or its base case changed since this run started: its result is not the
      // one the study now asks for, and running the study would refuse it.
      fmt::print("{:<{}}  {:<9}  holds another case or other --set values than the study plans\n",
                 j.name, width, "mismatch");
      continue;
    }
    if (st == RunState::Finished || st == RunState::Failed) {
      ++finished;
      try {
        const RunMetrics m = read_run_metrics(j.dir, t0, t1);
        what = fmt::format("{}: {:.3f} kg out in {:.2f} s (mean {:.3f} kg/s), wall {:.0f} s",
                           m.error.empty() ? m.end : m.error, m.discharged_mass_kg,
                           m.discharge_time_s, m.mean_rate_kg_s, m.wall_time_s);
      } catch (const std::exception& e) {
        what = e.what();
      }
    } else if (const auto p = read_run_progress(j.dir)) {
      const std::string eta = std::isfinite(p->eta_s) ? fmt::format("{:.0f} s", p->eta_s) : "?";
      what = p->phase == "discharge"
                 ? fmt::format(
                       "discharge t = {:.2f} s, {:.3f} kg out ({:.1f}%), {:.3f} kg/s, "
                       "wall {:.0f} s, ETA {} (as of {})",
                       p->t_s, p->discharged_kg, 100 * p->fraction, p->rate_kg_s, p->wall_s, eta,
                       p->updated)
                 : fmt::format("{}, wall {:.0f} s (as of {})", p->phase, p->wall_s, p->updated);
    } else if (st != RunState::Absent) {
      what = "no progress.json (not written yet, or a run of a silodem before 2026-12-04)";
    }
    fmt::print("{:<{}}  {:<9}  {}\n", j.name, width, state, what);
  }
  fmt::print(
      "{} of {} runs done; {}\n", finished, jobs.size(),
      busy ? "a study is running in " + out.string() : "nothing is running in " + out.string());
}

}  // namespace

int study_command(const StudyOptions& o) {
  const Study s = load_study(o.study_path);
  const fs::path out(o.out_dir);
  struct Row {
    std::vector<std::string> labels;
    std::int64_t seed;
  };
  std::vector<RunJob> jobs;
  std::vector<Row> rows;
  for (const auto& p : grid(s)) {
    for (const auto seed : s.seeds) {
      RunJob j;
      Row r{{}, seed};
      std::string name;
      j.overrides = s.fixed;
      for (std::size_t d = 0; d < s.vary.size(); ++d) {
        const Vary& v = s.vary[d];
        name += v.name + "=" + path_safe(v.labels[p[d]]) + "_";
        r.labels.push_back(v.labels[p[d]]);
        j.overrides.insert(j.overrides.end(), v.sets[p[d]].begin(), v.sets[p[d]].end());
      }
      j.overrides.push_back(set_item("simulation.seed", std::to_string(seed)));
      j.name = name + "seed=" + std::to_string(seed);
      j.dir = out / "runs" / j.name;
      j.case_path = s.base;
      jobs.push_back(std::move(j));
      rows.push_back(std::move(r));
    }
  }
  // Two grid points with one name would share a directory (a repeated value, or labels that
  // differ only in characters a directory name cannot hold).
  for (std::size_t i = 0; i < jobs.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (jobs[i].name == jobs[k].name)
        throw InputError({o.study_path, 0, 0}, "vary",
                         fmt::format("two runs would both be named '{}' (a value listed twice, or "
                                     "labels equal after replacing characters other than "
                                     "letters, digits, '.', '+', '-' by '-')",
                                     jobs[i].name));
  // Every run's case is checked before anything starts: a bad key or value is one error now,
  // not a failed run an hour in.
  for (const auto& j : jobs) {
    try {
      const Case c = config::load_case_file(j.case_path, j.overrides);
      if (!c.silo.present)
        throw InputError({s.base, 0, 0}, "base", "a study needs a silo case (a [silo] section)");
    } catch (const InputError& e) {
      throw InputError({o.study_path, 0, 0}, "", fmt::format("run {}: {}", j.name, e.what()));
    }
  }
  if (o.status) {
    print_status(jobs, out, s.window_t0, s.window_t1);
    return kExitOk;
  }
  if (o.dry_run) {
    for (const auto& j : jobs) {
      fmt::print("{}  {}", (out / "runs" / j.name).string(), to_string(run_state(j.dir)));
      for (const auto& s2 : j.overrides) fmt::print(" --set '{}'", s2);
      fmt::print("\n");
    }
    fmt::print("{} runs, every case checked\n", jobs.size());
    return kExitOk;
  }
  JobRunner::lock(out);
  for (const auto& j : jobs) check_run_matches(j, "study");
  if (!fs::exists(out / "study.toml") || !fs::equivalent(o.study_path, out / "study.toml"))
    fs::copy_file(o.study_path, out / "study.toml", fs::copy_options::overwrite_existing);
  {
    toml::array names, numeric;
    for (const auto& v : s.vary) names.push_back(v.name), numeric.push_back(v.numeric);
    const toml::table meta{{"title", s.title},
                           {"base", s.base},
                           {"study_file", fs::absolute(o.study_path).string()},
                           {"vary", names},
                           {"vary_numeric", numeric},
                           {"window_s", toml::array{s.window_t0, s.window_t1}},
                           {"runs", int64_t(jobs.size())}};
    write_text(out / "study.json", to_json(meta));
  }
  std::vector<std::optional<RunMetrics>> metrics(jobs.size());
  std::vector<RunState> states(jobs.size(), RunState::Absent);
  auto write_csv = [&] {
    std::vector<std::string> cols = {"run"};
    for (const auto& v : s.vary) cols.push_back(v.name);
    cols.push_back("seed");
    for (const auto& c : metric_columns()) cols.push_back(c);
    std::string text;
    for (std::size_t i = 0; i < cols.size(); ++i) text += (i ? "," : "") + cols[i];
    text += "\n";
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      std::vector<std::string> cells = {jobs[i].name};
      for (const auto& l : rows[i].labels) cells.push_back(csv_text(l));
      cells.push_back(std::to_string(rows[i].seed));
      for (const auto& c : metric_cells(metrics[i] ? &*metrics[i] : nullptr, states[i]))
        cells.push_back(c);
      for (std::size_t k = 0; k < cells.size(); ++k) text += (k ? "," : "") + cells[k];
      text += "\n";
    }
    write_text(out / "study.csv", text);
  };
  ProgressLine progress;
  JobRunner runner(o.threads, o.jobs, out / "logs", s.run_reports);
  fmt::print("study {}: {} runs ({} points x {} seeds) into {}, {} at a time, {} thread(s) each\n",
             s.title.empty() ? o.study_path : s.title, jobs.size(), jobs.size() / s.seeds.size(),
             s.seeds.size(), out.string(), o.jobs, runner.threads_per_job());
  std::fflush(stdout);
  const auto outcomes = runner.run(
      jobs,
      [&](std::size_t i) {
        states[i] = run_state(jobs[i].dir);
        try {
          metrics[i] = read_run_metrics(jobs[i].dir, s.window_t0, s.window_t1);
        } catch (const std::exception& e) {
          fmt::print(stderr, "\nwarning: run {}: {}\n", jobs[i].name, e.what());
        }
        write_csv();
      },
      [&](std::size_t done, std::size_t running, double eta) {
        progress.show(runner_status("study", done, jobs.size(), running, eta, progress.elapsed()));
      });
  progress.finish();
  for (std::size_t i = 0; i < jobs.size(); ++i) states[i] = outcomes[i].state;
  write_csv();
  std::size_t finished = 0, failed = 0;
  for (const auto st : states)
    finished += st == RunState::Finished, failed += st == RunState::Failed;
  if (runner.interrupted()) {
    fmt::print(stderr,
               "study interrupted: {} of {} runs done, the running ones checkpointed; continue "
               "with the same command\n",
               finished + failed, jobs.size());
    return kExitInterrupted;
  }
  fmt::print(
      "study: {} runs finished, {} failed (a guard stopped them; see {}), {} unfinished; "
      "wrote {}\n",
      finished, failed, (out / "logs").string(), jobs.size() - finished - failed,
      (out / "study.csv").string());
  const int status = finished + failed < jobs.size() ? 1 : failed > 0 ? kExitSimulation : kExitOk;
  const int rc = run_tool("silodem_study.py", {out.string()}, true);
  return status != kExitOk ? status : rc;
}

}  // namespace silodem::app
