// SPDX-License-Identifier: MIT
// No tangential force (frictionless contacts).
#pragma once
#include <array>

#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct TangentialNone {
  static constexpr Slot slot = Slot::Tangential;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "frictionless";

  static constexpr std::array<double, 0> history{};
  struct Params {};

  SILODEM_HOT static Vec3 kernel(const Params&, const ContactGeometry&, const NormalForce&, double,
                                 double*, double) {
    return {};
  }
  static std::vector<Field> fields(bool) { return {}; }
  static Params configure(const ParamValues&, const LawContext&) { return {}; }
};

}  // namespace silodem
