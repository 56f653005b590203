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

// One law per slot for one kind of pair (coal a - coal b, or coal a - wall).
struct ContactLaw {
  NormalKernel normal = nullptr;
  NormalParams np;
  TangentialKernel tangential = nullptr;
  TangentialParams tp;
  RollingKernel rolling = nullptr;
  RollingParams rp;
  CohesionKernel cohesion = nullptr;
  CohesionParams cp;
  bool rolling_spring = false;      // the rolling law keeps a spring in the contact history
  std::string law_names[4];         // by Slot, for reports
  int law_index[4] = {0, 0, 0, 0};  // by Slot: position of the law in its list (laws.hpp)
};

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
  // Checks the validated values against each other and fills the slot of `law`.
  void (*configure)(const ParamValues& values, const LawContext& ctx, ContactLaw& law);
  int index;  // position in its slot's list (laws.hpp); selects the compiled kernel (dispatch.hpp)
};

const std::vector<LawEntry>& contact_laws();
const LawEntry* find_law(Slot slot, std::string_view name);
std::vector<std::string> law_names(Slot slot);

}  // namespace silodem
