// SPDX-License-Identifier: MIT
#include "io/run_metrics.hpp"

#include "io/csv.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace fs = std::filesystem;

namespace silodem {
namespace {

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot open '{}'", file.string()));
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(fmt::format("'{}' is not valid JSON: {}", file.string(), e.what()));
  }
}

double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : RunMetrics::nan;
}

std::string string_or_empty(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

}  // namespace

const char* to_string(RunState s) {
  switch (s) {
    case RunState::Absent:
      return "absent";
    case RunState::Restart:
      return "restart";
    case RunState::Resumable:
      return "resumable";
    case RunState::Finished:
      return "finished";
    case RunState::Failed:
      return "failed";
  }
  return "?";
}

RunState run_state(const fs::path& dir) {
  if (!fs::exists(dir) || (fs::is_directory(dir) && fs::is_empty(dir))) return RunState::Absent;
  const bool checkpoint = fs::is_regular_file(dir / "checkpoint.bin");
  const fs::path summary = dir / "summary.json";
  if (fs::is_regular_file(summary)) {
    bool complete = false;
    std::string error, end;
    try {
      const nlohmann::json j = read_json(summary);
      complete = j.is_object() && j.value("complete", false);
      if (j.is_object()) error = string_or_empty(j, "error"), end = string_or_empty(j, "end");
    } catch (const std::exception&) {
      // written atomically by `run`, so only a foreign or hand-edited file gets here
    }
    if (complete) return RunState::Finished;
    // A guard stopped it: the same case would stop again, so the error is the run's result. An
    // output failure (a full disk) keeps its checkpoint to be resumed once the cause is fixed.
    const bool output_failure = end.find("(output)") != std::string::npos;
    if (!error.empty() && end.rfind("interrupted", 0) != 0 && !(output_failure && checkpoint))
      return RunState::Failed;
  }
  return checkpoint ? RunState::Resumable : RunState::Restart;
}

std::vector<OutletRow> read_outlet_csv(const fs::path& file) {
  const CsvTable t = read_csv_table(file.string());
  const std::size_t t0 = t.column("t_start_s"), t1 = t.column("t_end_s"), m = t.column("mass_kg");
  std::vector<OutletRow> rows;
  rows.reserve(t.rows.size());
  for (std::size_t r = 0; r < t.rows.size(); ++r)  // an empty bin's mass cell may be blank
    rows.push_back({t.number(r, t0), t.number(r, t1), t.rows[r][m].empty() ? 0.0 : t.number(r, m)});
  return rows;
}

double window_rate(const std::vector<OutletRow>& bins, double t0, double t1, bool emptied,
                   double discharge_time) {
  if (emptied && std::isfinite(discharge_time)) t1 = std::min(t1, discharge_time);
  if (!(t1 > t0)) return RunMetrics::nan;
  double mass = 0.0;
  for (const auto& b : bins) {
    const double w = b.t_end - b.t_start;
    const double overlap = std::min(b.t_end, t1) - std::max(b.t_start, t0);
    if (w > 0.0 && overlap > 0.0) mass += b.mass * overlap / w;
  }
  return mass / (t1 - t0);
}

RunMetrics read_run_metrics(const fs::path& dir, double t0, double t1) {
  const nlohmann::json j = read_json(dir / "summary.json");
  if (!j.is_object())
    throw std::runtime_error(
        fmt::format("'{}' is not a JSON object", (dir / "summary.json").string()));
  RunMetrics m;
  m.complete = j.contains("complete") && j["complete"].is_boolean() && j["complete"].get<bool>();
  m.flow_stopped =
      j.contains("flow_stopped") && j["flow_stopped"].is_boolean() && j["flow_stopped"].get<bool>();
  m.end = string_or_empty(j, "end");
  m.error = string_or_empty(j, "error");
  m.filled_mass_kg = number_or_nan(j, "filled_mass_kg");
  m.discharged_mass_kg = number_or_nan(j, "discharged_mass_kg");
  m.discharge_time_s = number_or_nan(j, "discharge_time_s");
  m.mean_rate_kg_s = number_or_nan(j, "mean_rate_kg_s");
  m.outlet_mean_calorific_kcal_kg = number_or_nan(j, "outlet_mean_calorific_kcal_kg");
  m.wall_time_s = number_or_nan(j, "wall_time_s");
  m.k = number_or_nan(j, "k");
  if (const auto it = j.find("particles_lost"); it != j.end() && it->is_number_integer())
    m.particles_lost = it->get<long>();
  // A run stopped by its time limit says nothing about what came after: its window ends there.
  const double end_time = number_or_nan(j, "discharge_end_time_s");
  if (m.end == "time limit" && std::isfinite(end_time)) t1 = std::min(t1, end_time);
  if (t1 > t0 && fs::is_regular_file(dir / "outlet.csv"))
    m.window_rate_kg_s =
        window_rate(read_outlet_csv(dir / "outlet.csv"), t0, t1, m.emptied(), m.discharge_time_s);
  return m;
}

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names = {
      "discharged_mass_kg", "discharge_time_s",    "mean_rate_kg_s",
      "window_rate_kg_s",   "discharged_fraction", "outlet_mean_calorific_kcal_kg",
      "wall_time_s"};
  return names;
}

double metric_value(const RunMetrics& m, const std::string& name) {
  if (name == "discharged_mass_kg") return m.discharged_mass_kg;
  if (name == "discharge_time_s") return m.discharge_time_s;
  if (name == "mean_rate_kg_s") return m.mean_rate_kg_s;
  if (name == "window_rate_kg_s") return m.window_rate_kg_s;
  if (name == "discharged_fraction") return m.discharged_mass_kg / m.filled_mass_kg;
  if (name == "outlet_mean_calorific_kcal_kg") return m.outlet_mean_calorific_kcal_kg;
  if (name == "wall_time_s") return m.wall_time_s;
  std::string all;
  for (const auto& n : metric_names()) all += (all.empty() ? "" : ", ") + n;
  throw std::invalid_argument(fmt::format("unknown metric '{}' (one of: {})", name, all));
}

double calibration_value(const RunMetrics& m, const std::string& name) {
  const double v = metric_value(m, name);
  if (name == "discharge_time_s" && !m.emptied()) return std::numeric_limits<double>::infinity();
  if (name == "mean_rate_kg_s" && m.flow_stopped) return 0.0;
  return v;
}

}  // namespace silodem
