// SPDX-License-Identifier: MIT
#include "app/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <cstdio>

namespace silodem::app {

ProgressLine::ProgressLine()
    : tty_(isatty(STDERR_FILENO) != 0), t0_(std::chrono::steady_clock::now()), last_(t0_) {}

double ProgressLine::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
}

void ProgressLine::show(const std::string& text, bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_ < std::chrono::milliseconds(tty_ ? 500 : 5000)) return;
  std::fflush(stdout);  // results (stdout) and progress (stderr) stay in order in a log
  last_ = now;
  if (tty_) {
    fmt::print(stderr, "\r\033[K{}", text);
    open_ = true;
  } else {
    fmt::print(stderr, "{}\n", text);
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (open_) fmt::print(stderr, "\n");
  open_ = false;
}

}  // namespace silodem::app
