// SPDX-License-Identifier: MIT
// No cohesion (dry material).
#pragma once
#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionNone {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "dry";

  SILODEM_HOT static double kernel(const CohesionParams&, const ContactGeometry&) { return 0.0; }
  // The common keys (pair_rule, wall_factor, factor) are accepted and have no effect, so that a
  // cohesive case can be switched dry with one `--set ...cohesion.law=none`.
  static std::vector<Field> fields(bool wall) { return cohesion_common_fields(wall); }
  static void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
    law.cp = CohesionParams{};
    law.cohesion = &kernel;
  }
};

}  // namespace silodem
