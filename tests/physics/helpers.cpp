// SPDX-License-Identifier: MIT
#include "helpers.hpp"

#include <stdexcept>
#include <variant>

#include "model/contact/dispatch.hpp"

namespace silodem::test {
namespace {

SlotChoice choice(Slot slot, const std::string& law, const std::map<std::string, double>& nums,
                  const std::map<std::string, std::string>& strs, bool wall) {
  const LawEntry* e = find_law(slot, law);
  if (!e) throw std::invalid_argument("no law " + law);
  SlotChoice c;
  c.law = law;
  c.values.section = std::string("test.") + slot_name(slot);
  for (const Field& f : e->fields(wall)) {
    if (f.kind == FieldKind::String) {
      c.values.strings[f.key] = f.default_string;
    } else if (f.default_number) {
      c.values.numbers[f.key] = *f.default_number * f.to_si;
    }
  }
  for (const auto& [k, v] : nums) c.values.numbers[k] = v, c.values.given[k] = true;
  for (const auto& [k, v] : strs) c.values.strings[k] = v, c.values.given[k] = true;
  return c;
}

}  // namespace

ContactSpec spec_of(const Laws& l, bool wall) {
  ContactSpec s;
  s.normal = choice(Slot::Normal, l.normal, l.normal_p, {}, wall);
  s.tangential = choice(Slot::Tangential, l.tangential, l.tangential_p, {}, wall);
  s.rolling = choice(Slot::Rolling, l.rolling, l.rolling_p, {}, wall);
  s.cohesion = choice(Slot::Cohesion, l.cohesion, l.cohesion_p, l.cohesion_s, wall);
  return s;
}

ContactModel model_of(const Laws& pp, const std::vector<double>& cohesion_cg, const Laws* wall,
                      CoarseGraining cg) {
  return ContactModel::build(spec_of(pp, false), spec_of(wall ? *wall : pp, true), cohesion_cg, cg,
                             nullptr);
}

ContactLaw law_of(const Laws& l, bool wall, double f_i, double f_j, CoarseGraining cg) {
  LawContext ctx{&cg, f_i, f_j, wall, nullptr};
  return configure_contact_law(spec_of(l, wall), ctx);
}

NormalForce normal_force(const ContactLaw& law, const ContactGeometry& g) {
  return with_kernels(law, [&](auto k) {
    using N = typename decltype(k)::Normal;
    return N::kernel(law.params<N>(), g, nullptr);
  });
}

NormalForce normal_force_with(const ContactLaw& law, const ContactGeometry& g, ContactState& s) {
  return with_kernels(law, [&](auto k) {
    using N = typename decltype(k)::Normal;
    return N::kernel(law.params<N>(), g, s.h);
  });
}

double normal_stiffness(const ContactLaw& law) {
  return law.params<NormalLinearSpringDashpot>().stiffness;
}

double cohesion_force(const ContactLaw& law) {
  return std::visit(
      [](const auto& p) {
        if constexpr (requires { p.force; }) return p.force;
        return 0.0;
      },
      law.cohesion);
}

}  // namespace silodem::test
