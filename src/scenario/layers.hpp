// SPDX-License-Identifier: MIT
// Scenario notation (PHYSICS.md 5): "L3-I2" lists coals from the top down with their number of
// height segments: Longwanggou in the top three, Indonesian in the bottom two.
#pragma once
#include <string>
#include <vector>

namespace silodem {

struct Layer {
  std::string symbol;  // coal symbol, e.g. "L"
  int segments = 0;
};

// Throws std::invalid_argument with a message saying what is wrong.
std::vector<Layer> parse_scenario(const std::string& name);
// Coal symbol of each filled segment, bottom (H1) first.
std::vector<std::string> segments_bottom_up(const std::vector<Layer>& layers);

}  // namespace silodem
