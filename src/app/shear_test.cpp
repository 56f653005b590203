// SPDX-License-Identifier: MIT
// `silodem shear-test CASE --out DIR [--preshear KPA] [--normal KPA,...] [--coal NAME] [--json]`:
// the FT-4 shear test (scenario/shear_cell.hpp) on each coal of a case. Writes DIR/shear_test.json
// (the results), DIR/points.csv (every pre-shear and failure point), DIR/series_<coal>.csv (the
// stresses through the whole test) and DIR/figures/yield_locus_<coal>.png (the locus with both
// Mohr circles); --json prints the JSON on stdout as well. `--refit FROM --out DIR [--failure
// peak-tau]` evaluates a finished test's recorded series again with another failure criterion
// (the same evaluation as a run's, so the same trajectory gives the same points), running nothing.
// A test checkpoints to DIR/shear_checkpoint.bin every [simulation] checkpoint_wall_interval s of
// wall time and on SIGINT/SIGTERM (exit 130); the same command with --resume continues it, with
// the same series and result as a test never interrupted (with the same threads).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/commands.hpp"
#include "app/signals.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/config/load.hpp"
#include "io/csv.hpp"
#include "scenario/shear_cell.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

std::vector<double> kpa_list(const std::string& text, const char* option) {
  std::vector<double> v;
  std::size_t a = 0;
  while (a <= text.size()) {
    std::size_t b = text.find(',', a);
    if (b == std::string::npos) b = text.size();
    const std::string cell = text.substr(a, b - a);
    const auto x = parse_number(cell);
    if (!x || !(*x > 0) || !std::isfinite(*x))
      throw InputError(
          {}, option,
          fmt::format("'{}' is not a positive number of kPa (give e.g. 7,6,5,4,3)", cell));
    v.push_back(*x * 1e3);
    a = b + 1;
  }
  return v;
}

std::string safe_name(const std::string& s) {
  std::string o;
  for (char ch : s) o += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-') ? ch : '_';
  return o;
}

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

// The fields that follow from the failure points: what --refit replaces.
nlohmann::json locus_json(const ShearTestResult& r) {
  nlohmann::json locus = nlohmann::json::array();
  for (const auto& p : r.points) locus.push_back({p.sigma / 1e3, p.tau / 1e3});
  const YieldLocus& y = r.locus;
  return {
      {"cohesion_kpa", y.cohesion / 1e3},
      {"friction_angle_deg", y.friction_angle / units::deg},
      {"unconfined_yield_kpa", y.unconfined_yield / 1e3},
      {"major_consolidation_kpa", y.major_consolidation / 1e3},
      {"ffc", finite_or_null(y.flow_function)},
      {"yield_locus", locus},
      {"fit_rms_residual_kpa", y.rms_residual / 1e3},
      {"cohesion_stderr_kpa", finite_or_null(y.cohesion_stderr / 1e3)},
      {"friction_angle_stderr_deg", finite_or_null(y.friction_angle_stderr / units::deg)},
      {"consolidation_circle_tangent", y.consolidation_tangent},
      {"mohr_unconfined_kpa", {y.unconfined.centre / 1e3, y.unconfined.radius / 1e3}},
      {"mohr_consolidation_kpa", {y.consolidation.centre / 1e3, y.consolidation.radius / 1e3}},
      {"warnings", r.warnings},
  };
}

nlohmann::json result_json(const ShearTestResult& r, const CoalProperties& coal,
                           const ShearTestSpec& spec, double wall_time) {
  nlohmann::json pre = nlohmann::json::array();
  for (const auto& p : r.points) pre.push_back({p.preshear.sigma / 1e3, p.preshear.tau / 1e3});
  nlohmann::json j = locus_json(r);
  j.update(nlohmann::json{
      {"coal", r.coal},
      {"bulk_density_kg_m3", r.bulk_density},
      {"solid_fraction", r.solid_fraction},
      {"preshear_kpa", {r.preshear.sigma / 1e3, r.preshear.tau / 1e3}},
      {"preshear_points", pre},
      {"preshear_steady", r.preshear_steady},
      {"preshear_strain", r.preshear_strain},
      {"measured",
       {{"cohesion_kpa", coal.cohesion / 1e3},
        {"friction_angle_deg", coal.friction_angle / units::deg},
        {"bulk_density_kg_m3", coal.bulk_density}}},
      {"cell",
       {{"particles", r.particles},
        {"glued", r.glued},
        {"width_mm", r.width * 1e3},
        {"sheared_height_mm", r.sheared_height * 1e3},
        {"mean_cg_diameter_mm", r.mean_diameter * 1e3},
        {"shear_velocity_m_s", r.shear_velocity},
        {"inertial_number", spec.inertial_number},
        {"time_step_s", r.dt},
        {"steps", r.steps},
        {"wall_time_s", wall_time}}},
  });
  return j;
}

void write_points(const fs::path& file, const std::vector<ShearTestResult>& results) {
  CsvWriter w(file.string(), {"coal", "kind", "point", "sigma_target_kpa", "sigma_kpa", "tau_kpa",
                              "strain_at_peak", "steady"});
  for (const auto& r : results)
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      const ShearPoint& p = r.points[k];
      const std::string i = std::to_string(k + 1);
      w.row(std::vector<std::string>{
          r.coal, "preshear", i, fmt::format("{:.17g}", r.preshear.sigma / 1e3),
          fmt::format("{:.17g}", p.preshear.sigma / 1e3),
          fmt::format("{:.17g}", p.preshear.tau / 1e3), "", p.preshear_steady ? "1" : "0"});
      w.row(std::vector<std::string>{
          r.coal, "failure", i, fmt::format("{:.17g}", p.sigma_target / 1e3),
          fmt::format("{:.17g}", p.sigma / 1e3), fmt::format("{:.17g}", p.tau / 1e3),
          fmt::format("{:.17g}", p.strain_at_peak), ""});
    }
  w.finish();
}

void write_series(const fs::path& file, const ShearTestResult& r) {
  CsvWriter w(file.string(),
              {"time_s", "phase", "point", "strain", "sigma_kpa", "tau_kpa", "height_mm"});
  for (const auto& s : r.series)
    w.row(std::vector<std::string>{
        fmt::format("{:.17g}", s.time), s.phase, std::to_string(s.point),
        fmt::format("{:.17g}", s.strain), fmt::format("{:.17g}", s.sigma / 1e3),
        fmt::format("{:.17g}", s.tau / 1e3), fmt::format("{:.17g}", s.height * 1e3)});
  w.finish();
}

// Prints each coal's result in one line, or the JSON.
void print_results(const nlohmann::json& doc, const fs::path& out, bool json) {
  if (json) {
    fmt::print("{}", doc.dump(2) + "\n");
    return;
  }
  // "+- se" after C and phi: the fit's standard error (yield_locus.hpp), empty with two points.
  const auto pm = [](const nlohmann::json& se, const char* f) {
    return se.is_number() ? fmt::format(fmt::runtime(f), se.get<double>()) : std::string();
  };
  for (const auto& r : doc["coals"])
    fmt::print(
        "{}: C = {:.3f}{} kPa (measured {:.3f}), phi = {:.1f}{} deg (measured {:.1f}), f_c = "
        "{:.3f} kPa, sigma_1 = {:.3f} kPa, ffc = {}, bulk density {:.0f} kg/m3 "
        "(measured {:.0f})\n",
        r["coal"].get<std::string>(), r["cohesion_kpa"].get<double>(),
        pm(r["cohesion_stderr_kpa"], " +- {:.3f}"), r["measured"]["cohesion_kpa"].get<double>(),
        r["friction_angle_deg"].get<double>(), pm(r["friction_angle_stderr_deg"], " +- {:.1f}"),
        r["measured"]["friction_angle_deg"].get<double>(), r["unconfined_yield_kpa"].get<double>(),
        r["major_consolidation_kpa"].get<double>(),
        r["ffc"].is_null() ? std::string("inf (no cohesion)")
                           : fmt::format("{:.2f}", r["ffc"].get<double>()),
        r["bulk_density_kg_m3"].get<double>(), r["measured"]["bulk_density_kg_m3"].get<double>());
  fmt::print("wrote {}\n", (out / "shear_test.json").string());
}

// Writes the JSON (then removes `done_with`, if given: the checkpoint of the test it completes),
// draws the figures (tools/silodem_shear.py) and prints; the tool's exit code.
int finish(const nlohmann::json& doc, const fs::path& out, bool json,
           const fs::path& done_with = {}) {
  write_atomically((out / "shear_test.json").string(), {doc.dump(2) + "\n"}, false);
  if (!done_with.empty()) fs::remove(done_with);
  std::vector<std::string> tool_args = {out.string()};
  if (json) tool_args.insert(tool_args.begin(), "--quiet");  // stdout is the JSON's
  const int rc = run_tool("silodem_shear.py", tool_args, /*quiet_if_unavailable=*/true);
  print_results(doc, out, json);
  return rc;
}

constexpr const char* kCheckpoint = "shear_checkpoint.bin";

void require_new_dir(const std::string& dir) {
  const fs::path out(dir);
  if (fs::exists(out / kCheckpoint))
    throw InputError({}, "--out",
                     fmt::format("'{}' holds an interrupted test's checkpoint: add --resume to "
                                 "continue it, or give another directory",
                                 dir));
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
    throw InputError({}, "--out", fmt::format("'{}' exists and is not empty", dir));
}

// The procedure's version in the signature: bump it when a change to run_shear_test would make a
// checkpoint of the old procedure go on differently, so that --resume refuses it.
constexpr const char* kProcedure = "shear-test procedure 1 (2026-12-07)";

// What a checkpoint must have been written by to be continued: this procedure, the case file as
// it reads now, the overrides, the coals and every option that changes the test (not --threads
// or --set simulation.threads, which change only the summation order: the result warns then).
std::uint64_t test_signature(const ShearTestOptions& o, const ShearTestSpec& spec,
                             const std::vector<int>& coals) {
  std::string t = std::string(kProcedure) + "\n" + read_text(o.case_path);
  for (const auto& s : o.overrides)
    if (s.rfind("simulation.threads=", 0) != 0) t += "\n--set " + s;
  t += "\ncoals";
  for (int c : coals) t += fmt::format(" {}", c);
  t += fmt::format("\npreshear {:a} normals", spec.preshear);
  for (double x : spec.normals) t += fmt::format(" {:a}", x);
  t += fmt::format(
      "\ncell {:a} {:a} I {:a} strains {:a} {:a} {:a} {:a} {:a} steady {:a} {:a} {:a} {:a} "
      "failure {} seed {}",
      spec.width, spec.height, spec.inertial_number, spec.preshear_strain, spec.preshear_max_strain,
      spec.represhear_strain, spec.failure_strain, spec.sample_strain, spec.steady_step,
      spec.steady_window, spec.steady_height_change, spec.steady_ratio_change,
      failure_criterion_name(spec.failure), spec.seed);
  return text_hash(t);
}

// A checkpoint's head: what it was written by and the coals it finished. Its reader is then at
// the state of the coal under way, if `current`.
struct TestCheckpoint {
  std::uint64_t signature = 0;
  std::vector<ShearTestResult> done;
  std::vector<double> done_wall;  // s, each finished coal's
  double current_wall = 0.0;      // s, spent on the coal under way before the checkpoint
  bool current = false;
};

void put_head(ByteWriter& w, const TestCheckpoint& h) {
  w.tag("SHTE");
  w.put(h.signature), w.put(std::uint64_t(h.done.size()));
  for (std::size_t k = 0; k < h.done.size(); ++k)
    save_shear_result(w, h.done[k]), w.put(h.done_wall[k]);
  w.put(h.current_wall), w.put(std::uint8_t(h.current));
}

TestCheckpoint get_head(ByteReader& r) {
  TestCheckpoint h;
  r.tag("SHTE");
  r.get(h.signature);
  const std::size_t n = r.get_count(8);
  for (std::size_t k = 0; k < n; ++k) {
    h.done.push_back(load_shear_result(r));
    h.done_wall.push_back(r.get<double>());
  }
  r.get(h.current_wall);
  h.current = r.get<std::uint8_t>() != 0;
  return h;
}

// --refit: a finished test's series (series_<coal>.csv), pre-shear points (shear_test.json,
// points.csv) and targets evaluated again by `spec.failure`, exactly as run_shear_test evaluates
// its own rows; everything else is carried over. Everything is read and evaluated before DIR is
// made, so a refused refit leaves nothing.
int refit_command(const ShearTestOptions& o, ShearTestSpec spec) {
  const fs::path from(o.refit), out(o.out_dir);
  require_new_dir(o.out_dir);
  nlohmann::json doc;
  std::vector<ShearTestResult> results;
  try {
    doc = nlohmann::json::parse(read_text(from / "shear_test.json"));
    const CsvTable points = read_csv_table((from / "points.csv").string());
    const std::size_t c_coal = points.column("coal"), c_kind = points.column("kind"),
                      c_point = points.column("point"), c_steady = points.column("steady");
    std::vector<double> normals;
    for (const auto& x : doc.at("normal_kpa")) normals.push_back(x.get<double>() * 1e3);
    // A test written before the JSON kept its failure strain had --failure-strain's.
    spec.failure_strain = doc.value("failure_strain", o.failure_strain);
    if (o.failure_strain_given && spec.failure_strain != o.failure_strain)
      throw InputError({}, "--failure-strain",
                       fmt::format("{:g}: '{}' was sheared to {:g} (its shear_test.json)",
                                   o.failure_strain, from.string(), spec.failure_strain));
    for (auto& j : doc.at("coals")) {
      ShearTestResult r;
      r.coal = j.at("coal").get<std::string>();
      r.preshear = {j.at("preshear_kpa").at(0).get<double>() * 1e3,
                    j.at("preshear_kpa").at(1).get<double>() * 1e3};
      for (const auto& w : j.at("warnings").get<std::vector<std::string>>())
        if (w.find(kNoPeakWarning) == std::string::npos) r.warnings.push_back(w);
      const CsvTable series =
          read_csv_table((from / fmt::format("series_{}.csv", safe_name(r.coal))).string());
      const std::size_t ct = series.column("time_s"), cph = series.column("phase"),
                        cpt = series.column("point"), cg = series.column("strain"),
                        cs = series.column("sigma_kpa"), ctau = series.column("tau_kpa"),
                        ch = series.column("height_mm");
      double largest_strain = 0;
      for (std::size_t i = 0; i < series.rows.size(); ++i) {
        const auto& row = series.rows[i];
        r.series.push_back({row[cph], int(series.number(i, cpt)), series.number(i, ct),
                            series.number(i, cg), series.number(i, cs) * 1e3,
                            series.number(i, ctau) * 1e3, series.number(i, ch) * 1e-3});
        if (row[cph] == "shear") largest_strain = std::max(largest_strain, r.series.back().strain);
      }
      if (!(largest_strain >= spec.failure_strain))
        throw InputError({}, "--failure-strain",
                         fmt::format("{:g}: the longest shear of {} in '{}' reached only {:g}",
                                     spec.failure_strain, r.coal, from.string(), largest_strain));
      const auto& pre = j.at("preshear_points");
      if (pre.size() != normals.size())
        throw InputError({}, "--refit",
                         fmt::format("'{}': {} has {} pre-shear points for {} normal stresses",
                                     from.string(), r.coal, pre.size(), normals.size()));
      for (std::size_t k = 0; k < normals.size(); ++k) {
        ShearPoint sp;
        sp.sigma_target = normals[k];
        sp.preshear = {pre.at(k).at(0).get<double>() * 1e3, pre.at(k).at(1).get<double>() * 1e3};
        for (const auto& row : points.rows)
          if (row[c_coal] == r.coal && row[c_kind] == "preshear" &&
              row[c_point] == std::to_string(k + 1))
            sp.preshear_steady = row[c_steady] == "1";
        r.points.push_back(sp);
      }
      evaluate_failure(r, spec);
      j.update(locus_json(r));
      results.push_back(std::move(r));
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError({}, "--refit",
                     fmt::format("'{}' does not hold a shear test's shear_test.json: {}",
                                 from.string(), e.what()));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // a file, a cell, a failed evaluation
    throw InputError({}, "--refit", e.what());
  }
  fs::create_directories(out / "figures");
  for (const auto& r : results)
    write_series(out / fmt::format("series_{}.csv", safe_name(r.coal)), r);
  write_points(out / "points.csv", results);
  doc["failure_criterion"] = failure_criterion_name(spec.failure);
  doc["failure_strain"] = spec.failure_strain;
  doc["refit_from"] = fs::absolute(from).lexically_normal().string();
  return finish(doc, out, o.json);
}

}  // namespace

int shear_test_command(const ShearTestOptions& o) {
  ShearTestSpec spec;
  spec.failure = o.failure == "peak-tau" ? FailureCriterion::PeakTau : FailureCriterion::PeakRatio;
  if (!o.refit.empty()) {
    if (!o.case_path.empty())
      throw InputError({}, "--refit", "evaluates a finished test again: give no case");
    return refit_command(o, spec);
  }
  if (o.case_path.empty()) throw InputError({}, "case", "a case file is needed (or --refit DIR)");
  spec.preshear = o.preshear_kpa * 1e3;
  if (!(spec.preshear > 0) || !std::isfinite(spec.preshear))
    throw InputError({}, "--preshear", fmt::format("{:g} kPa: must be positive", o.preshear_kpa));
  if (!o.normals.empty()) spec.normals = kpa_list(o.normals, "--normal");
  if (o.preshear_kpa != 9.0 && o.normals.empty()) {
    // The standard test's ratios: 7/9 .. 3/9 of the pre-shear stress.
    spec.normals.clear();
    for (double f : {7.0, 6.0, 5.0, 4.0, 3.0}) spec.normals.push_back(spec.preshear * f / 9.0);
  }
  spec.threads = o.threads;
  spec.seed = o.seed;
  spec.width = o.width;
  spec.height = o.height;
  spec.inertial_number = o.inertial_number;
  spec.preshear_strain = o.preshear_strain;
  spec.preshear_max_strain = o.preshear_max_strain_given
                                 ? o.preshear_max_strain
                                 : std::max(o.preshear_max_strain, o.preshear_strain);
  spec.represhear_strain = o.represhear_strain;
  spec.failure_strain = o.failure_strain;

  check_shear_spec(spec);
  const Case c = config::load_case_file(o.case_path, o.overrides);
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  std::vector<int> coals;
  for (std::size_t k = 0; k < c.coals.size(); ++k)
    if (o.coal.empty() || c.coals[k].name == o.coal) coals.push_back(int(k));
  if (coals.empty()) {
    std::string names;
    for (const auto& cp : c.coals) names += (names.empty() ? "" : ", ") + cp.name;
    throw InputError({}, "--coal",
                     fmt::format("'{}' is not a coal of the case ({})", o.coal, names));
  }
  const fs::path out(o.out_dir), checkpoint = out / kCheckpoint;
  TestCheckpoint state;
  state.signature = test_signature(o, spec, coals);
  std::optional<ByteReader> reader;
  if (o.resume) {
    if (!fs::exists(checkpoint))
      throw InputError({}, "--resume",
                       fs::exists(out / "shear_test.json")
                           ? fmt::format("'{}' holds a finished test: nothing to resume", o.out_dir)
                           : fmt::format("'{}' has no {} (a test killed before its first "
                                         "checkpoint starts again without --resume, into an "
                                         "empty directory)",
                                         o.out_dir, kCheckpoint));
    TestCheckpoint head;
    try {
      reader.emplace(read_checkpoint(checkpoint.string()));
      head = get_head(*reader);
    } catch (const std::runtime_error& e) {  // foreign, damaged, of another version
      throw InputError({}, "--resume", fmt::format("{}: {}", checkpoint.string(), e.what()));
    }
    if (head.signature != state.signature)
      throw InputError({}, "--resume",
                       fmt::format("'{}' was written by a test of another case file, --set, coal "
                                   "or test option: give the interrupted test's command again",
                                   checkpoint.string()));
    if (head.done.size() >= coals.size())
      throw InputError(
          {}, "--resume",
          fmt::format("'{}' has every coal finished: nothing to resume", checkpoint.string()));
    state.done = std::move(head.done);
    state.done_wall = std::move(head.done_wall);
    state.current_wall = head.current_wall;
    if (!head.current) reader.reset();  // the next coal starts from its beginning
  } else {
    require_new_dir(o.out_dir);
  }
  fs::create_directories(out / "figures");

  const double interval = c.time.checkpoint_wall_interval;
  using Clock = std::chrono::steady_clock;
  auto last_write = Clock::now();
  // The head, then the state of the coal under way (none between two coals).
  auto write = [&](const std::function<void(ByteWriter&)>& current) {
    ByteWriter w;
    state.current = bool(current);
    put_head(w, state);
    if (current) current(w);
    write_checkpoint(checkpoint.string(), w);
    last_write = Clock::now();
  };
  {
    SignalGuard signals;
    for (std::size_t i = state.done.size(); i < coals.size(); ++i) {
      const auto t0 = Clock::now();
      const double before = state.current_wall;
      auto elapsed = [&] {
        return before + std::chrono::duration<double>(Clock::now() - t0).count();
      };
      ShearCheckpointing ck;
      ck.stop = [] { return stop_signal() != 0; };
      ck.due = [&] {
        return interval > 0 &&
               std::chrono::duration<double>(Clock::now() - last_write).count() >= interval;
      };
      ck.write = [&](const std::function<void(ByteWriter&)>& current) {
        state.current_wall = elapsed();
        write(current);
      };
      ck.resume = reader ? &*reader : nullptr;
      const auto progress = [&](const std::string& m) {
        if (!o.json) fmt::print(stderr, "{}\n", m);
      };
      try {
        state.done.push_back(run_shear_test(c, report, model, coals[i], spec, progress, &ck));
      } catch (const ShearResumeError& e) {
        throw InputError({}, "--resume", fmt::format("{}: {}", checkpoint.string(), e.what()));
      } catch (const ShearInterrupted&) {
        fmt::print(stderr,
                   "interrupted by signal {}; checkpoint written; continue with the same command "
                   "and --resume\n",
                   stop_signal());
        return kExitInterrupted;
      }
      reader.reset();
      state.done_wall.push_back(elapsed());
      state.current_wall = 0.0;
      write_series(out / fmt::format("series_{}.csv", safe_name(state.done.back().coal)),
                   state.done.back());
      if (i + 1 < coals.size()) write({});  // the finished coal is kept if the next one is killed
    }
  }
  const std::vector<ShearTestResult>& results = state.done;
  nlohmann::json all = nlohmann::json::array();
  for (std::size_t i = 0; i < coals.size(); ++i)
    all.push_back(
        result_json(results[i], c.coals[std::size_t(coals[i])], spec, state.done_wall[i]));
  write_points(out / "points.csv", results);
  const nlohmann::json doc = {{"case", c.path},
                              {"k", c.cg.k},
                              {"preshear_kpa", spec.preshear / 1e3},
                              {"normal_kpa",
                               [&] {
                                 std::vector<double> v;
                                 for (double s : spec.normals) v.push_back(s / 1e3);
                                 return v;
                               }()},
                              {"failure_criterion", failure_criterion_name(spec.failure)},
                              {"failure_strain", spec.failure_strain},
                              {"preshear_min_strain", spec.preshear_strain},
                              {"preshear_max_strain", spec.preshear_max_strain},
                              {"coals", all}};
  return finish(doc, out, o.json, checkpoint);
}

}  // namespace silodem::app
