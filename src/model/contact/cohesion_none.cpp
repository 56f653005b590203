// SPDX-License-Identifier: MIT
// No cohesion (dry material).
#include "model/contact/cohesion_common.hpp"

namespace silodem {
namespace {

double kernel(const CohesionParams&, const ContactGeometry&) {
  return 0.0;
}
// The common keys (pair_rule, wall_factor, factor) are accepted and have no effect, so that a
// cohesive case can be switched dry with one `--set ...cohesion.law=none`.
std::vector<Field> fields(bool wall) {
  return cohesion_common_fields(wall);
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
