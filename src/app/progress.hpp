// SPDX-License-Identifier: MIT
// A progress line: redrawn in place on a terminal, a new line every few seconds otherwise (logs).
#pragma once
#include <chrono>
#include <string>

namespace silodem::app {

class ProgressLine {
 public:
  ProgressLine();
  // Shows `text` if enough wall time has passed since the last one (or `force`).
  void show(const std::string& text, bool force = false);
  void finish();  // ends a redrawn line
  double elapsed() const;

 private:
  bool tty_;
  bool open_ = false;
  std::chrono::steady_clock::time_point t0_, last_;
};

}  // namespace silodem::app
