// SPDX-License-Identifier: MIT
#include "model/coarse_graining.hpp"

#include <fmt/format.h>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace silodem {

RestitutionPolicy restitution_policy_from_name(const std::string& name) {
  if (name == "energy") return RestitutionPolicy::Energy;
  if (name == "energy-clamped") return RestitutionPolicy::EnergyClamped;
  if (name == "none") return RestitutionPolicy::None;
  throw std::invalid_argument("unknown restitution policy '" + name + "'");
}

const char* restitution_policy_name(RestitutionPolicy p) {
  switch (p) {
    case RestitutionPolicy::Energy:
      return "energy";
    case RestitutionPolicy::EnergyClamped:
      return "energy-clamped";
    case RestitutionPolicy::None:
      return "none";
  }
  return "?";
}

double CoarseGraining::cohesion_force(double f_l) const {
  return std::pow(k, cohesion_exponent) * f_l;  // Eq. 13 (alpha = 3 in the paper)
}

RestitutionCg restitution_cg(double e, const CoarseGraining& cg) {
  RestitutionCg r;
  r.argument = 1.0 + (e * e - 1.0) * cg.k;  // radicand of Eq. 11
  switch (cg.restitution_policy) {
    case RestitutionPolicy::None:
      r.value = e;
      return r;
    case RestitutionPolicy::Energy:
      if (r.argument <= 0.0) {  // = 0 gives e_cg = 0: ln 0, no finite damping
        r.defined = false;
        r.value = 0.0;
        r.warning = fmt::format(
            "Eq. 11 has no real value for e = {:g} at k = {:g} (1 + (e^2 - 1) k = {:.4g} <= 0; "
            "defined only for k <= {:.4g}); choose restitution_policy = \"energy-clamped\" or "
            "\"none\"",
            e, cg.k, r.argument, 1.0 / (1.0 - e * e));
        return r;
      }
      r.value = std::sqrt(r.argument);
      return r;
    case RestitutionPolicy::EnergyClamped: {
      const double raw = r.argument > 0.0 ? std::sqrt(r.argument) : 0.0;
      r.defined = r.argument > 0.0;
      if (raw < cg.restitution_floor) {
        r.clamped = true;
        r.value = cg.restitution_floor;
        r.warning = fmt::format(
            "Eq. 11 gives {} for e = {:g} at k = {:g} (1 + (e^2 - 1) k = {:.4g}); clamped to the "
            "floor e_min = {:g}",
            r.defined ? fmt::format("{:.4g}", raw) : std::string("no real value"), e, cg.k,
            r.argument, cg.restitution_floor);
      } else {
        r.value = raw;
      }
      return r;
    }
  }
  return r;
}

double damping_ratio(double e) {
  const double l = std::log(e);
  return std::fabs(l) / std::sqrt(kPi * kPi + l * l);
}

double normal_damping(double k_n, double m_eff, double e) {
  return 2.0 * damping_ratio(e) * std::sqrt(m_eff * k_n);
}

double collision_time(double k_n, double m_eff, double e) {
  const double eta = normal_damping(k_n, m_eff, e);
  return kPi / std::sqrt(k_n / m_eff - eta * eta / (4.0 * m_eff * m_eff));
}

double effective_mass(double m_i, double m_j) {
  return m_j > 0.0 ? m_i * m_j / (m_i + m_j) : m_i;
}

const std::vector<Bound<CoarseGraining>>& coarse_graining_fields() {
  using F = Field;
  using S = CoarseGraining;
  static const std::vector<Bound<S>> b = {
      bind(F::number("k", "each simulated sphere stands for k^3 particles; k = 1 is plain DEM")
               .at_least(1)
               .at_most(100),
           &S::k),
      bind(F::number("cohesion_exponent", "alpha in F_L,cg = k^alpha F_L (paper: 3; Rumpf: 2)")
               .at_least(2)
               .at_most(3),
           &S::cohesion_exponent),
      bind<S>(F::text("restitution_policy",
                      "e_cg: Eq. 11 (energy), Eq. 11 clamped to restitution_floor, or e unchanged",
                      {"energy", "energy-clamped", "none"},
                      restitution_policy_name(S{}.restitution_policy)),
              [](S& s, const ParamValues& v) {
                s.restitution_policy = restitution_policy_from_name(v.string("restitution_policy"));
              }),
      bind(F::number("restitution_floor", "e_min for energy-clamped").above(0).at_most(1),
           &S::restitution_floor),
      bind(F::number("rumpf_porosity",
                     "eps in Eq. 14 (F_L = d_sv^2 sigma_t eps / (1 - eps)) for every coal: the "
                     "porosity of the packing whose tensile strength the contacts must give; 0 = "
                     "each coal's Eq. 15 from its measured densities (the paper)")
               .at_least(0)
               .at_most(0.9),
           &S::rumpf_porosity),
  };
  return b;
}

}  // namespace silodem
