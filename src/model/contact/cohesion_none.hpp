// SPDX-License-Identifier: MIT
// No cohesion (dry material).
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/cohesion_common.hpp"

namespace silodem {
struct CohesionNone {
  static constexpr Slot slot = Slot::Cohesion;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "dry";

  static constexpr std::array<double, 0> history{};
  struct Params {
    double reach_over_d = 0.0;
  };

  SILODEM_HOT static double kernel(const Params&, const ContactGeometry&, const NormalForce&,
                                   double*) {
    return 0.0;
  }
  // The common keys (pair_rule, wall_factor, factor) are accepted and have no effect, so that a
  // cohesive case can be switched dry with one `--set ...cohesion.law=none`.
  static std::vector<Field> fields(bool wall) { return cohesion_common_fields(wall); }
  static Params configure(const ParamValues&, const LawContext&) { return {}; }
};

}  // namespace silodem
