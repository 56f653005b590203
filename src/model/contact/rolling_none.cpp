// SPDX-License-Identifier: MIT
// No rolling resistance.
#include "model/contact/registry.hpp"

namespace silodem {
namespace {

RollingTorque kernel(const RollingParams&, const ContactGeometry&, const NormalParams&,
                     const NormalForce&, double, Vec3& spring, double) {
  spring = Vec3{};
  return {};
}
std::vector<Field> fields(bool) {
  return {};
}
void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
  law.rolling = &kernel;
}

}  // namespace

LawEntry rolling_none_entry() {
  return {"none", Slot::Rolling, "no rolling resistance", &fields, &configure};
}

}  // namespace silodem
