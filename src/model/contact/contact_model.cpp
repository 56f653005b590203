// SPDX-License-Identifier: MIT
#include "model/contact/contact_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "model/contact/dispatch.hpp"

namespace silodem {

ContactLaw configure_contact_law(const ContactSpec& spec, const LawContext& ctx) {
  ContactLaw law;
  // Slot order: the history values are laid out in it.
  const std::pair<Slot, const SlotChoice*> slots[] = {{Slot::Normal, &spec.normal},
                                                      {Slot::Tangential, &spec.tangential},
                                                      {Slot::Rolling, &spec.rolling},
                                                      {Slot::Cohesion, &spec.cohesion}};
  for (const auto& [slot, choice] : slots) {
    const LawEntry* e = find_law(slot, choice->law);
    if (!e) throw choice->values.error("law", "unknown law '" + choice->law + "'");
    e->configure(choice->values, ctx, law);
    const int s = static_cast<int>(slot);
    law.law_names[s] = choice->law;
    law.law_index[s] = e->index;
    // The state layout, in slot order (dispatch.hpp's HistoryOf computes the same offsets).
    StateLayout& L = law.layout;
    if (L.size + e->history > kMaxHistory)
      throw choice->values.error("law", "the four contact laws keep more than " +
                                            std::to_string(kMaxHistory) +
                                            " history values per contact together");
    L.offset[s] = L.size;
    L.count[s] = e->history;
    L.law[s] = choice->law;
    for (int k = 0; k < e->history; ++k) L.swap[L.size + k] = e->swap[k];
    L.size += e->history;
  }
  return law;
}

double applied_cohesion_force(const ContactLaw& law) {
  return std::visit(
      [](const auto& p) {
        if constexpr (requires { p.force; })
          return double(p.force);
        else
          return std::numeric_limits<double>::quiet_NaN();
      },
      law.cohesion);
}

bool CoalContactValues::empty() const {
  for (const auto& v : slot)
    if (!v.numbers.empty()) return false;
  return true;
}

double mix_values(const std::string& mixing, double x, double y) {
  if (mixing == "min") return std::min(x, y);
  if (mixing == "harmonic") return x == 0.0 || y == 0.0 ? 0.0 : 2.0 / (1.0 / x + 1.0 / y);
  return 0.5 * x + 0.5 * y;
}

ContactSpec spec_for(const ContactSpec& spec, int a, int b) {
  ContactSpec out = spec;
  out.per_coal.clear();
  auto values_of = [&](int coal, int s) -> const ParamValues* {
    if (coal < 0 || std::size_t(coal) >= spec.per_coal.size()) return nullptr;
    const ParamValues& v = spec.per_coal[std::size_t(coal)].slot[s];
    return v.numbers.empty() ? nullptr : &v;
  };
  SlotChoice* slots[4] = {&out.normal, &out.tangential, &out.rolling, &out.cohesion};
  for (int s = 0; s < 4; ++s) {
    const ParamValues* va = values_of(a, s);
    const ParamValues* vb = b == a ? nullptr : values_of(b, s);
    if (!va && !vb) continue;
    ParamValues& v = slots[s]->values;
    const ParamValues& base = v;
    std::map<std::string, double> merged;
    std::map<std::string, SourcePlace> places;
    for (const ParamValues* over : {va, vb}) {
      if (!over) continue;
      // Not a structured binding: clang 14 cannot capture one in the lambda below.
      for (const auto& entry : over->numbers) {
        const std::string& key = entry.first;
        if (merged.count(key)) continue;
        auto value = [&](const ParamValues* o) {
          if (o) {
            auto it = o->numbers.find(key);
            if (it != o->numbers.end()) return it->second;
          }
          return base.number(key);
        };
        const double xa = value(va);
        merged[key] = b < 0 || b == a ? xa : mix_values(spec.mixing, xa, value(vb));
        places[key] = over->places.count(key) ? over->places.at(key) : over->place;
      }
    }
    for (const auto& [key, x] : merged) {
      v.numbers[key] = x;
      v.given[key] = true;
      v.places[key] = places[key];
    }
    v.section = (va ? va : vb)->section;
  }
  return out;
}

ContactModel ContactModel::build(const ContactSpec& pp, const ContactSpec& pw,
                                 const std::vector<double>& cohesion_cg, const CoarseGraining& cg,
                                 std::vector<std::string>* warnings) {
  ContactModel m;
  m.n_ = static_cast<int>(cohesion_cg.size());
  std::vector<std::string> raw;
  m.pp_.resize(std::size_t(m.n_) * std::size_t(m.n_));
  // Each coal's own contacts first (its values unmixed), so that a per-coal value that does not
  // fit the section's others is reported as that coal's before any mixed pair is built.
  for (int a = 0; a < m.n_; ++a) {
    m.pp_[std::size_t(a * m.n_ + a)] = configure_contact_law(
        spec_for(pp, a, a), {&cg, cohesion_cg[a], cohesion_cg[a], false, &raw});
    m.pw_.push_back(
        configure_contact_law(spec_for(pw, a, -1), {&cg, cohesion_cg[a], 0.0, true, &raw}));
  }
  for (int a = 0; a < m.n_; ++a)
    for (int b = 0; b < m.n_; ++b) {
      if (a == b) continue;
      try {
        m.pp_[std::size_t(a * m.n_ + b)] = configure_contact_law(
            spec_for(pp, a, b), {&cg, cohesion_cg[a], cohesion_cg[b], false, &raw});
      } catch (const InputError& e) {
        if (pp.per_coal.empty() || pp.coal_names.size() != std::size_t(m.n_)) throw;
        throw InputError(
            e.place(), e.key(),
            e.message() + fmt::format(" (in the contacts of coal \"{}\" with coal \"{}\", whose "
                                      "values are the \"{}\" mean of the two coals')",
                                      pp.coal_names[std::size_t(a)], pp.coal_names[std::size_t(b)],
                                      pp.mixing));
      }
    }
  for (const auto& l : m.pp_) m.max_reach_ = std::max(m.max_reach_, l.reach_over_d);
  for (const auto& l : m.pw_) m.max_reach_ = std::max(m.max_reach_, l.reach_over_d);
  if (warnings) {
    for (const auto& w : raw)
      if (std::find(warnings->begin(), warnings->end(), w) == warnings->end())
        warnings->push_back(w);
  }
  return m;
}

double normal_elastic_energy(const ContactLaw& law, const ContactGeometry& g,
                             const ContactState& s) {
  return with_kernels(law, [&](auto k) {
    using N = typename decltype(k)::Normal;
    return N::elastic_energy(law.params<N>(), g, s.h);  // the normal law's values come first
  });
}

double normal_collision_time(const ContactLaw& law, double m_eff, double r_eff) {
  return with_kernels(law, [&](auto k) {
    using N = typename decltype(k)::Normal;
    return N::collision_time(law.params<N>(), m_eff, r_eff);
  });
}

double normal_damping_coefficient(const ContactLaw& law, double m_eff, double r_eff) {
  return with_kernels(law, [&](auto k) {
    using N = typename decltype(k)::Normal;
    return N::damping_coefficient(law.params<N>(), m_eff, r_eff);
  });
}

double ContactModel::pair_collision_time(int a, int b, double m_a, double m_b, double r_a,
                                         double r_b) const {
  return normal_collision_time(pair(a, b), effective_mass(m_a, m_b), r_a * r_b / (r_a + r_b));
}

double ContactModel::wall_collision_time(int a, double m, double r) const {
  return normal_collision_time(wall(a), m, r);
}

ContactResult evaluate_contact(const ContactLaw& law, const ContactGeometry& g, ContactState& s,
                               double dt) {
  return with_kernels(law, [&](auto k) {
    using K = decltype(k);
    return evaluate<K>(typed_params<K>(law), g, s, dt);
  });
}

}  // namespace silodem
