// SPDX-License-Identifier: MIT
#include "model/contact/contact_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "model/contact/dispatch.hpp"

namespace silodem {

ContactLaw configure_contact_law(const ContactSpec& spec, const LawContext& ctx) {
  ContactLaw law;
  // Order matters: tangential and rolling read k_n from the normal slot.
  const std::pair<Slot, const SlotChoice*> slots[] = {{Slot::Normal, &spec.normal},
                                                      {Slot::Tangential, &spec.tangential},
                                                      {Slot::Rolling, &spec.rolling},
                                                      {Slot::Cohesion, &spec.cohesion}};
  for (const auto& [slot, choice] : slots) {
    const LawEntry* e = find_law(slot, choice->law);
    if (!e) throw choice->values.error("law", "unknown law '" + choice->law + "'");
    e->configure(choice->values, ctx, law);
    law.law_names[static_cast<int>(slot)] = choice->law;
    law.law_index[static_cast<int>(slot)] = e->index;
  }
  return law;
}

ContactModel ContactModel::build(const ContactSpec& pp, const ContactSpec& pw,
                                 const std::vector<double>& cohesion_cg, const CoarseGraining& cg,
                                 std::vector<std::string>* warnings) {
  ContactModel m;
  m.n_ = static_cast<int>(cohesion_cg.size());
  std::vector<std::string> raw;
  for (int a = 0; a < m.n_; ++a) {
    for (int b = 0; b < m.n_; ++b) {
      LawContext ctx{&cg, cohesion_cg[a], cohesion_cg[b], false, &raw};
      m.pp_.push_back(configure_contact_law(pp, ctx));
    }
  }
  for (int a = 0; a < m.n_; ++a) {
    LawContext ctx{&cg, cohesion_cg[a], 0.0, true, &raw};
    m.pw_.push_back(configure_contact_law(pw, ctx));
  }
  for (const auto& l : m.pp_) m.max_reach_ = std::max(m.max_reach_, l.cp.reach_over_d);
  for (const auto& l : m.pw_) m.max_reach_ = std::max(m.max_reach_, l.cp.reach_over_d);
  if (warnings) {
    for (const auto& w : raw)
      if (std::find(warnings->begin(), warnings->end(), w) == warnings->end())
        warnings->push_back(w);
  }
  return m;
}

static double t_col(const NormalParams& np, double m_eff) {
  // Eq. 10 with E3: t_col = pi / sqrt(k/m - eta^2 / (4 m^2)), eta = 2 zeta sqrt(m k)
  // => t_col = pi / sqrt((k/m)(1 - zeta^2)).
  return kPi / std::sqrt(np.stiffness / m_eff * (1.0 - np.damping_ratio * np.damping_ratio));
}

double ContactModel::pair_collision_time(int a, int b, double m_a, double m_b) const {
  return t_col(pair(a, b).np, effective_mass(m_a, m_b));
}

double ContactModel::wall_collision_time(int a, double m) const {
  return t_col(wall(a).np, m);
}

ContactResult evaluate_contact(const ContactLaw& law, const ContactGeometry& g, ContactState& s,
                               double dt) {
  return with_kernels(law, [&](auto k) { return evaluate<decltype(k)>(law, g, s, dt); });
}

}  // namespace silodem
