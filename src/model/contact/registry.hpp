// SPDX-License-Identifier: MIT
// The table of contact laws (one line per law, in registry.cpp) and what a law must provide.
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
  std::string law_names[4];  // by Slot, for reports
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
};

const std::vector<LawEntry>& contact_laws();
const LawEntry* find_law(Slot slot, std::string_view name);
std::vector<std::string> law_names(Slot slot);

}  // namespace silodem
