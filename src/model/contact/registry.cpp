// SPDX-License-Identifier: MIT
// THE list of contact laws. To add one: write src/model/contact/<slot>_<name>.cpp defining
// `LawEntry <slot>_<name>_entry()` (fields, a configure function that checks parameters once,
// and a pure kernel citing its equation), declare it below, add one line to the table, add a test
// in tests/unit/model/ and a page in docs/models/.
#include "model/contact/registry.hpp"

namespace silodem {

LawEntry normal_linear_spring_dashpot_entry();
LawEntry tangential_none_entry();
LawEntry tangential_linear_history_entry();
LawEntry rolling_none_entry();
LawEntry rolling_mfix_entry();
LawEntry rolling_epsd_entry();
LawEntry cohesion_none_entry();
LawEntry cohesion_overlap_only_entry();
LawEntry cohesion_constant_range_entry();
LawEntry cohesion_mfix_like_entry();

const std::vector<LawEntry>& contact_laws() {
  static const std::vector<LawEntry> table = {
      normal_linear_spring_dashpot_entry(),
      tangential_none_entry(),
      tangential_linear_history_entry(),
      rolling_none_entry(),
      rolling_mfix_entry(),
      rolling_epsd_entry(),
      cohesion_none_entry(),
      cohesion_overlap_only_entry(),
      cohesion_constant_range_entry(),
      cohesion_mfix_like_entry(),
  };
  return table;
}

const char* slot_name(Slot s) {
  switch (s) {
    case Slot::Normal:
      return "normal";
    case Slot::Tangential:
      return "tangential";
    case Slot::Rolling:
      return "rolling";
    case Slot::Cohesion:
      return "cohesion";
  }
  return "?";
}

const LawEntry* find_law(Slot slot, std::string_view name) {
  for (const auto& e : contact_laws())
    if (e.slot == slot && name == e.name) return &e;
  return nullptr;
}

std::vector<std::string> law_names(Slot slot) {
  std::vector<std::string> out;
  for (const auto& e : contact_laws())
    if (e.slot == slot) out.emplace_back(e.name);
  return out;
}

}  // namespace silodem
