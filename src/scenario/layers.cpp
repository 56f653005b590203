// SPDX-License-Identifier: MIT
#include "scenario/layers.hpp"

#include <cctype>
#include <stdexcept>

namespace silodem {

std::vector<Layer> parse_scenario(const std::string& name) {
  std::vector<Layer> out;
  std::size_t i = 0;
  auto fail = [&](const std::string& why) {
    throw std::invalid_argument("scenario \"" + name + "\": " + why +
                                " (expected coal symbols with segment counts, top first, e.g. "
                                "\"L3-I2\")");
  };
  if (name.empty()) fail("empty");
  while (i < name.size()) {
    Layer l;
    while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i])))
      l.symbol += name[i++];
    if (l.symbol.empty())
      fail("a layer must start with a coal symbol at position " + std::to_string(i + 1));
    std::string digits;
    while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i])))
      digits += name[i++];
    if (digits.empty()) fail("layer '" + l.symbol + "' has no segment count");
    if (digits.size() > 3) fail("segment count '" + digits + "' is too large");
    l.segments = std::stoi(digits);
    if (l.segments < 1) fail("layer '" + l.symbol + "' has zero segments");
    if (!out.empty() && out.back().symbol == l.symbol)
      fail("two adjacent layers of the same coal '" + l.symbol + "'");
    out.push_back(l);
    if (i < name.size()) {
      if (name[i] != '-') fail(std::string("unexpected character '") + name[i] + "'");
      ++i;
      if (i == name.size()) fail("ends with '-'");
    }
  }
  return out;
}

std::vector<std::string> segments_bottom_up(const std::vector<Layer>& layers) {
  std::vector<std::string> out;
  for (auto it = layers.rbegin(); it != layers.rend(); ++it)
    for (int k = 0; k < it->segments; ++k) out.push_back(it->symbol);
  return out;
}

}  // namespace silodem
