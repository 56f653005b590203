// SPDX-License-Identifier: MIT
// The case-file schema: one Field list per section. Validation (io/config/load.cpp), `silodem
// check` and docs/config.md all come from these lists.
#pragma once
#include <string>
#include <vector>

#include "core/schema.hpp"

namespace silodem::config {

struct Section {
  std::string name;  // "simulation", "coal", ...
  std::string doc;
  bool array = false;  // [[name]]
  std::vector<Field> fields;
};

// Top-level sections with fixed fields (contact slots and walls depend on the chosen law/type).
const std::vector<Section>& sections();
const Section& section(const std::string& name);
// Top-level keys a case file may contain.
std::vector<std::string> top_level_keys();

// [contact.particle_particle] mixing: how a pair of two coals combines their per-coal values.
Field contact_mixing_field();

// Closest candidate by edit distance, or empty when nothing is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

// docs/config.md
std::string markdown();

}  // namespace silodem::config
