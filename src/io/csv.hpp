// SPDX-License-Identifier: MIT
// CSV output written to "<name>.partial" and renamed when complete, so an interrupted run never
// leaves a file that looks finished.
#pragma once
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace silodem {

class CsvWriter {
 public:
  CsvWriter(std::string path, const std::vector<std::string>& columns);
  // Continues "<path>.partial" of an interrupted run: cut back to `bytes` (its size at the
  // checkpoint) and append from there.
  CsvWriter(std::string path, std::size_t ncol, std::uint64_t bytes);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  // Appends one row; numbers with 17 significant digits (round-trip exact).
  void row(const std::vector<double>& values);
  // Appends one row of already formatted cells (no quoting: cells must not contain commas).
  void row(const std::vector<std::string>& cells);
  // Flushes to the OS and returns the file's size in bytes (for a checkpoint).
  std::uint64_t flush();
  // Flushes, closes and renames to the final name.
  void finish();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
  std::size_t ncol_ = 0;
};

// A CSV file as this program writes it (a header line, no quoting): the header's column names
// and each later non-empty line's cells. column() finds a column by name. Errors (a missing file,
// a missing column, a row with another number of cells) throw std::runtime_error naming the file
// and line.
struct CsvTable {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;  // each row's line in the file
  std::size_t column(const std::string& name) const;
  double number(std::size_t row, std::size_t col) const;  // throws naming file:line
};
CsvTable read_csv_table(const std::string& path);
// The whole of `text` as a number (std::stod's syntax), or nothing.
std::optional<double> parse_number(const std::string& text);

}  // namespace silodem
