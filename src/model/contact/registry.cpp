// SPDX-License-Identifier: MIT
// The table of contact laws, built from the lists in laws.hpp.
#include "model/contact/registry.hpp"

#include "model/contact/contact_model.hpp"
#include "model/contact/laws.hpp"

namespace silodem {
namespace {

template <class Law>
void configure_law(const ParamValues& v, const LawContext& ctx, ContactLaw& law) {
  const typename Law::Params p = Law::configure(v, ctx);
  law.set_params<Law>(p);
  if constexpr (Law::slot == Slot::Cohesion) law.reach_over_d = p.reach_over_d;
}

template <class... Laws>
void append(std::vector<LawEntry>& table, LawList<Laws...>) {
  int index = 0;
  ((table.push_back({Laws::name, Laws::slot, Laws::summary, &Laws::fields, &configure_law<Laws>,
                     history_size<Laws>, Laws::history.data(), index++})),
   ...);
}

}  // namespace

const std::vector<LawEntry>& contact_laws() {
  static const std::vector<LawEntry> table = [] {
    std::vector<LawEntry> t;
    append(t, NormalLaws{});
    append(t, TangentialLaws{});
    append(t, RollingLaws{});
    append(t, CohesionLaws{});
    return t;
  }();
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
