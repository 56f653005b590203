// SPDX-License-Identifier: MIT
// No rolling resistance.
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct RollingNone {
  static constexpr Slot slot = Slot::Rolling;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "no rolling resistance";

  static constexpr std::array<double, 0> history{};
  struct Params {};

  SILODEM_HOT static RollingTorque kernel(const Params&, const ContactGeometry&, const NormalForce&,
                                          double, double*, double) {
    return {};
  }
  static std::vector<Field> fields(bool) { return {}; }
  static Params configure(const ParamValues&, const LawContext&) { return {}; }
};

}  // namespace silodem
