// SPDX-License-Identifier: MIT
#include "io/run_progress.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"

namespace fs = std::filesystem;

namespace silodem {
namespace {

constexpr const char* kFile = "progress.json";

nlohmann::json number(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : RunProgress::nan;
}

}  // namespace

void write_run_progress(const fs::path& dir, RunProgress p) {
  // UTC: fmt 9 formats a system_clock time point in local time.
  p.updated = fmt::format(
      "{:%Y-%m-%dT%H:%M:%SZ}",
      fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())));
  const nlohmann::json j = {{"phase", p.phase},
                            {"t_s", number(p.t_s)},
                            {"discharged_kg", number(p.discharged_kg)},
                            {"fraction", number(p.fraction)},
                            {"rate_kg_s", number(p.rate_kg_s)},
                            {"wall_s", number(p.wall_s)},
                            {"eta_s", number(p.eta_s)},
                            {"updated", p.updated}};
  write_text(dir / kFile, j.dump(2) + "\n");
}

std::optional<RunProgress> read_run_progress(const fs::path& dir) {
  const std::string text = read_text(dir / kFile);
  if (text.empty()) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("phase") || !j["phase"].is_string())
    return std::nullopt;
  RunProgress p;
  p.phase = j["phase"].get<std::string>();
  p.t_s = number_or_nan(j, "t_s");
  p.discharged_kg = number_or_nan(j, "discharged_kg");
  p.fraction = number_or_nan(j, "fraction");
  p.rate_kg_s = number_or_nan(j, "rate_kg_s");
  p.wall_s = number_or_nan(j, "wall_s");
  p.eta_s = number_or_nan(j, "eta_s");
  if (j.contains("updated") && j["updated"].is_string())
    p.updated = j["updated"].get<std::string>();
  return p;
}

void remove_run_progress(const fs::path& dir) {
  std::error_code ec;
  fs::remove(dir / kFile, ec);
}

double runs_eta(const std::vector<double>& running_left, const std::vector<double>& running_elapsed,
                std::size_t pending, double mean_run, int slots) {
  std::vector<double> free_at;  // when each slot is free, s from now
  for (std::size_t i = 0; i < running_left.size(); ++i) {
    double left = running_left[i];
    if (!std::isfinite(left) && std::isfinite(mean_run) && i < running_elapsed.size())
      left = std::max(0.0, mean_run - running_elapsed[i]);
    if (!std::isfinite(left)) return -1.0;
    free_at.push_back(std::max(0.0, left));
  }
  if (pending > 0 && !std::isfinite(mean_run)) return -1.0;
  while (free_at.size() < std::size_t(std::max(1, slots))) free_at.push_back(0.0);
  for (std::size_t k = 0; k < pending; ++k)
    *std::min_element(free_at.begin(), free_at.end()) += mean_run;
  return *std::max_element(free_at.begin(), free_at.end());
}

}  // namespace silodem
