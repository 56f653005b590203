// SPDX-License-Identifier: MIT
// No tangential force (frictionless contacts).
#pragma once
#include "core/inline.hpp"
#include "model/contact/registry.hpp"

namespace silodem {
struct TangentialNone {
  static constexpr Slot slot = Slot::Tangential;
  static constexpr const char* name = "none";
  static constexpr const char* summary = "frictionless";

  SILODEM_HOT static Vec3 kernel(const TangentialParams&, const ContactGeometry&, double, double,
                                 Vec3& spring, double) {
    spring = Vec3{};
    return {};
  }
  static std::vector<Field> fields(bool) { return {}; }
  static void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
    law.tangential = &kernel;
  }
};

}  // namespace silodem
