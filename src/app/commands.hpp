// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

namespace silodem::app {

struct RunOptions {
  std::string case_path;
  std::string out_dir;
  int threads = 0;
  std::vector<std::string> overrides;  // --set key=value
};

int run_command(const RunOptions& o);
int check_command(const std::string& case_path, bool json,
                  const std::vector<std::string>& overrides);

// Exit codes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInput = 2;       // bad case file or command line
inline constexpr int kExitSimulation = 3;  // the simulation went wrong
inline constexpr int kExitNotEmptied = 4;  // silo: the flow stopped (arching) or hit max_time

}  // namespace silodem::app
