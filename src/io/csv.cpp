// SPDX-License-Identifier: MIT
#include "io/csv.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace silodem {

CsvWriter::CsvWriter(std::string path, const std::vector<std::string>& columns)
    : path_(std::move(path)), ncol_(columns.size()) {
  f_ = std::fopen((path_ + ".partial").c_str(), "wb");
  if (!f_)
    throw std::runtime_error(
        fmt::format("cannot write {}.partial: {}", path_, std::strerror(errno)));
  fmt::print(f_, "{}\n", fmt::join(columns, ","));
}

CsvWriter::CsvWriter(std::string path, std::size_t ncol, std::uint64_t bytes)
    : path_(std::move(path)), ncol_(ncol) {
  const std::string partial = path_ + ".partial";
  std::error_code ec;
  // Finished already (the run stopped with an error after its last checkpoint, or was killed
  // while finishing): continue from the checkpoint's length all the same.
  if (!std::filesystem::exists(partial) && std::filesystem::exists(path_))
    std::filesystem::rename(path_, partial);
  if (!std::filesystem::exists(partial) || std::filesystem::file_size(partial, ec) < bytes)
    throw std::runtime_error(
        fmt::format("cannot resume {}: it is missing or shorter than at the checkpoint ({} bytes)",
                    partial, bytes));
  std::filesystem::resize_file(partial, bytes);
  f_ = std::fopen(partial.c_str(), "ab");
  if (!f_)
    throw std::runtime_error(fmt::format("cannot append to {}: {}", partial, std::strerror(errno)));
}

std::uint64_t CsvWriter::flush() {
  if (!f_) return 0;
  if (std::fflush(f_) != 0 || ::fsync(fileno(f_)) != 0)
    throw std::runtime_error("cannot write " + path_ + ".partial");
  return std::uint64_t(std::ftell(f_));
}

CsvWriter::~CsvWriter() {
  if (f_) std::fclose(f_);  // left as .partial: the run did not finish
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != ncol_) throw std::logic_error("CSV row has the wrong number of columns");
  std::string line;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (k) line += ',';
    if (!std::isnan(values[k])) line += fmt::format("{}", values[k]);  // NaN: an empty cell
  }
  fmt::print(f_, "{}\n", line);
}

void CsvWriter::row(const std::vector<std::string>& cells) {
  if (cells.size() != ncol_) throw std::logic_error("CSV row has the wrong number of columns");
  fmt::print(f_, "{}\n", fmt::join(cells, ","));
}

void CsvWriter::finish() {
  if (!f_) return;
  if (std::fflush(f_) != 0 || std::fclose(f_) != 0)
    throw std::runtime_error("cannot finish " + path_ + ": " + std::strerror(errno));
  f_ = nullptr;
  std::filesystem::rename(path_ + ".partial", path_);
}

namespace {
std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t a = 0;
  for (;;) {
    const std::size_t b = line.find(',', a);
    cells.push_back(line.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) return cells;
    a = b + 1;
  }
}
}  // namespace

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("cannot open '{}'", path));
  CsvTable t;
  t.path = path;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(fmt::format("'{}' is empty", path));
  if (!line.empty() && line.back() == '\r') line.pop_back();
  t.header = split_cells(line);
  for (int n = 2; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    auto cells = split_cells(line);
    if (cells.size() != t.header.size())
      throw std::runtime_error(fmt::format("{}:{}: {} cells, the header has {}", path, n,
                                           cells.size(), t.header.size()));
    t.rows.push_back(std::move(cells));
    t.lines.push_back(n);
  }
  return t;
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return k;
  throw std::runtime_error(fmt::format("'{}' has no column '{}'", path, name));
}

std::optional<double> parse_number(const std::string& text) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (text.empty() || used != text.size()) return std::nullopt;
  return x;
}

double CsvTable::number(std::size_t row, std::size_t col) const {
  const std::string& cell = rows.at(row).at(col);
  const auto x = parse_number(cell);
  if (!x)
    throw std::runtime_error(fmt::format("{}:{}: '{}' in column '{}' is not a number", path,
                                         lines.at(row), cell, header.at(col)));
  return *x;
}

}  // namespace silodem
