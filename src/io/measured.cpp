// SPDX-License-Identifier: MIT
#include "io/measured.hpp"

#include <fmt/format.h>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace silodem {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  for (char ch : line) {
    if (ch == ',')
      out.emplace_back();
    else if (ch != '\r')
      out.back() += ch;
  }
  for (auto& c : out) {  // trim blanks
    const auto a = c.find_first_not_of(" \t"), b = c.find_last_not_of(" \t");
    c = a == std::string::npos ? std::string() : c.substr(a, b - a + 1);
  }
  return out;
}

}  // namespace

MeasuredData load_measured_csv(const std::string& path, const SourcePlace& from) {
  const char* key = "output.measured";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(from, key, fmt::format("= \"{}\": not a readable file", path));
  if (std::filesystem::file_size(path, ec) > (std::uintmax_t(64) << 20))
    throw InputError(from, key, fmt::format("= \"{}\": larger than 64 MiB", path));
  std::ifstream in(path);
  if (!in) throw InputError(from, key, fmt::format("= \"{}\": cannot open the file", path));
  std::string line;
  if (!std::getline(in, line))
    throw InputError({path, 1, 1}, key, "the file is empty (expected a header row: t_s,...)");
  const auto header = split(line);
  int it = -1, ir = -1, ic = -1;
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == "t_s") it = int(k);
    if (header[k] == "rate_kg_s") ir = int(k);
    if (header[k] == "calorific_kcal_kg") ic = int(k);
  }
  if (it < 0 || (ir < 0 && ic < 0))
    throw InputError({path, 1, 1}, key,
                     fmt::format("header '{}' must name t_s and rate_kg_s and/or "
                                 "calorific_kcal_kg",
                                 line));
  MeasuredData m;
  m.has_rate = ir >= 0;
  m.has_calorific = ic >= 0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split(line);
    auto column_of = [&](int k) {
      int col = 1;
      for (int q = 0; q < k && q < int(cells.size()); ++q)
        col += int(cells[std::size_t(q)].size()) + 1;
      return col;
    };
    auto value = [&](int k, const char* name, double lo, bool required) {
      if (k < 0) return nan;
      if (k >= int(cells.size()) || cells[std::size_t(k)].empty()) {
        if (required)
          throw InputError({path, lineno, column_of(k)}, key, fmt::format("{} is missing", name));
        return nan;
      }
      const std::string& s = cells[std::size_t(k)];
      double x = 0.0;
      const auto res = std::from_chars(s.data(), s.data() + s.size(), x);
      if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(x))
        throw InputError({path, lineno, column_of(k)}, key,
                         fmt::format("{} = '{}' is not a number", name, s));
      if (x < lo)
        throw InputError({path, lineno, column_of(k)}, key,
                         fmt::format("{} = {} is out of range; allowed [{}, inf)", name, s, lo));
      return x;
    };
    const double t = value(it, "t_s", 0.0, true);
    if (!m.t.empty() && t <= m.t.back())
      throw InputError({path, lineno, column_of(it)}, key,
                       fmt::format("t_s = {} is not after the previous row's {}", t, m.t.back()));
    m.t.push_back(t);
    m.rate.push_back(value(ir, "rate_kg_s", 0.0, false));
    m.calorific.push_back(value(ic, "calorific_kcal_kg", 0.0, false));
  }
  if (m.t.empty()) throw InputError({path, 2, 1}, key, "no data rows after the header");
  return m;
}

}  // namespace silodem
