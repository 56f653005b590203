// SPDX-License-Identifier: MIT
// No cohesion (dry material).
#include "model/contact/cohesion_common.hpp"

namespace silodem {
namespace {

double kernel(const CohesionParams&, const ContactGeometry&) {
  return 0.0;
}
std::vector<Field> fields(bool) {
  return {};
}
void configure(const ParamValues&, const LawContext&, ContactLaw& law) {
  law.cp = CohesionParams{};
  law.cohesion = &kernel;
}

}  // namespace

LawEntry cohesion_none_entry() {
  return {"none", Slot::Cohesion, "dry", &fields, &configure};
}

}  // namespace silodem
