// SPDX-License-Identifier: MIT
// No rolling resistance.
#pragma once
#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct RollingNone {
  static constexpr Slot slot = Slot::Rolling;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "no rolling resistance";

  SILODEM_HOT static RollingTorque kernel(const RollingParams&, const ContactGeometry&,
                                          const NormalParams&, const NormalForce&, double,
                                          Vec3& spring, double) {
    spring = Vec3{};
    return {};
  }
  static std::vector<Field> fields(bool) { return {}; }
  static void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
    law.rolling = &kernel;
  }
};

}  // namespace silodem
