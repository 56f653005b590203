// SPDX-License-Identifier: MIT
// Scaling laws for the coarse-graining factor k (PHYSICS.md 1; paper Eq. 1-2, 11-13): every
// quantity that changes with k is derived here and nowhere else.
#pragma once
#include <string>
#include <vector>

#include "core/schema.hpp"

namespace silodem {

enum class RestitutionPolicy {
  Energy,         // Eq. 11, refused where 1 + (e^2 - 1) k <= 0
  EnergyClamped,  // Eq. 11, clamped to a floor e_min with a warning where undefined/below
  None,           // e_cg = e (Table 1's value applied to the CG particles)
};

RestitutionPolicy restitution_policy_from_name(const std::string& name);  // throws on unknown
const char* restitution_policy_name(RestitutionPolicy p);

struct CoarseGraining {
  double k = 1.0;                  // each CG sphere stands for k^3 original particles
  double cohesion_exponent = 3.0;  // F_L,cg = k^alpha F_L; 3 = paper (Bond number), 2 = Rumpf
  RestitutionPolicy restitution_policy = RestitutionPolicy::None;
  double restitution_floor = 0.01;  // e_min for EnergyClamped
  // eps in Eq. 14 for every coal; 0 = each coal's Eq. 15 (its measured packing, the paper's).
  // Rumpf's relation ties the bulk tensile strength to the contact force through the porosity of
  // the packing that carries it; a DEM bed that packs otherwise than the coal needs its own.
  double rumpf_porosity = 0.0;

  double diameter(double d) const { return k * d; }      // Eq. 2
  double mass(double m) const { return k * k * k * m; }  // Eq. 1
  double cohesion_force(double f_l) const;               // Eq. 13 with exponent alpha
};

struct RestitutionCg {
  double value = 0.0;     // e_cg actually used
  double argument = 0.0;  // 1 + (e^2 - 1) k, the radicand of Eq. 11
  bool defined = true;    // Eq. 11 has a real value
  bool clamped = false;   // EnergyClamped raised it to the floor
  std::string warning;    // non-empty when the user should know
};

// Eq. 11: e_cg = sqrt(1 + (e^2 - 1) k), following the policy. Never returns NaN: where Eq. 11 is
// undefined under the `energy` policy, `defined` is false and `value` is 0; the caller refuses it.
RestitutionCg restitution_cg(double e, const CoarseGraining& cg);

// Normal damping from restitution (Eq. 9 with the sign fixed, E2; general m_eff, E5):
// zeta = |ln e| / sqrt(pi^2 + ln^2 e), eta_n = 2 zeta sqrt(m_eff k_n).
double damping_ratio(double e);
double normal_damping(double k_n, double m_eff, double e);
// Eq. 10 with the factor 4 (E3): t_col = pi / sqrt(k_n/m_eff - eta_n^2 / (4 m_eff^2)).
double collision_time(double k_n, double m_eff, double e);
// Effective mass of a pair; pass m_j = 0 for a wall (m_eff = m_i).
double effective_mass(double m_i, double m_j);

// The [coarse_graining] keys, bound to CoarseGraining's members (defaults: above).
const std::vector<Bound<CoarseGraining>>& coarse_graining_fields();

}  // namespace silodem
