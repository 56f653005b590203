// SPDX-License-Identifier: MIT
// No tangential force (frictionless contacts).
#include "model/contact/registry.hpp"

namespace silodem {
namespace {

Vec3 kernel(const TangentialParams&, const ContactGeometry&, double, double, Vec3& spring, double) {
  spring = Vec3{};
  return {};
}
std::vector<Field> fields(bool) {
  return {};
}
void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
  law.tangential = &kernel;
}

}  // namespace

LawEntry tangential_none_entry() {
  return {"none", Slot::Tangential, "frictionless", &fields, &configure};
}

}  // namespace silodem
