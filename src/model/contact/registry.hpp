// SPDX-License-Identifier: MIT
// What a contact law provides and the table of laws (built from the lists in laws.hpp).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/schema.hpp"
#include "model/coarse_graining.hpp"
#include "model/contact/slots.hpp"

namespace silodem {

enum class Slot { Normal, Tangential, Rolling, Cohesion };
const char* slot_name(Slot s);

struct ContactLaw;  // contact_model.hpp: the four configured laws of one pair kind

// What a law may know when it is configured for one pair kind.
struct LawContext {
  const CoarseGraining* cg = nullptr;
  double cohesion_i = 0.0;  // F_L,cg of coal a (N)
  double cohesion_j = 0.0;  // F_L,cg of coal b; unused against a wall
  bool wall = false;
  std::vector<std::string>* warnings = nullptr;  // collected for `check`
};

struct LawEntry {
  const char* name;
  Slot slot;
  const char* summary;  // one line for docs and `check`
  std::vector<Field> (*fields)(bool wall);
  // Checks the validated values against each other and puts the law's Params into its slot of
  // `law` (registry.cpp, from the law's own `configure`).
  void (*configure)(const ParamValues& values, const LawContext& ctx, ContactLaw& law);
  int history;         // values the law keeps per contact
  const double* swap;  // their factors when i and j swap (`history` of them)
  int index;  // position in its slot's list (laws.hpp); selects the compiled kernel (dispatch.hpp)
};

const std::vector<LawEntry>& contact_laws();
const LawEntry* find_law(Slot slot, std::string_view name);
std::vector<std::string> law_names(Slot slot);

}  // namespace silodem
