// SPDX-License-Identifier: MIT
// THE list of wall shapes. To add one: src/engine/walls/<shape>.cpp with a Wall subclass and a
// `WallEntry <shape>_wall_entry()`, declared and listed below, plus a test.
#include "engine/walls/wall.hpp"

namespace silodem {

WallEntry plane_wall_entry();
WallEntry box_wall_entry();
WallEntry frustum_wall_entry();
WallEntry cylinder_wall_entry();

const std::vector<WallEntry>& wall_types() {
  static const std::vector<WallEntry> table = {
      plane_wall_entry(),
      box_wall_entry(),
      frustum_wall_entry(),
      cylinder_wall_entry(),
  };
  return table;
}

const WallEntry* find_wall_type(const std::string& name) {
  for (const auto& e : wall_types())
    if (name == e.name) return &e;
  return nullptr;
}

}  // namespace silodem
