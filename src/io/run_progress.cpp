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

void OutflowWindow::add(double t, double mass_out) {
  if (!s_.empty() && t < s_.back().first) s_.clear();  // time went back: a new run
  // The newest pair moves with each call until it is window/100 past the one before it.
  if (s_.size() >= 2 && t - s_[s_.size() - 2].first < window_ / 100)
    s_.back() = {t, mass_out};
  else
    s_.emplace_back(t, mass_out);
  // Keep one pair at or before t - window, so that the span covers the whole window.
  while (s_.size() > 2 && s_[1].first <= t - window_) s_.pop_front();
}

double OutflowWindow::rate() const {
  if (s_.size() < 2) return RunProgress::nan;
  // add() keeps the front at the newest pair at or before the window's start (else the oldest).
  const double span = s_.back().first - s_.front().first;
  if (span < 0.2 * window_) return RunProgress::nan;
  return (s_.back().second - s_.front().second) / span;
}

double discharge_eta(double cost, double n, double to_go, double rate, double time_left) {
  if (!(rate > 0) || !(cost > 0)) return RunProgress::nan;
  const double t_e = to_go / rate;
  if (!(t_e > 0)) return 0.0;
  const double t_run = std::min(t_e, std::max(0.0, time_left));
  return cost * n * t_run * (1.0 - 0.5 * t_run / t_e);
}

}  // namespace silodem
