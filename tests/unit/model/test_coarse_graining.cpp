// SPDX-License-Identifier: MIT
// T-U3 (restitution policy) and T-U4 (damping and collision time) of VERIFICATION.md 4.1.
#include <gtest/gtest.h>

#include <cmath>

#include "model/coarse_graining.hpp"

namespace silodem {
namespace {

CoarseGraining cg_of(double k, RestitutionPolicy p, double floor = 0.01) {
  CoarseGraining cg;
  cg.k = k;
  cg.restitution_policy = p;
  cg.restitution_floor = floor;
  return cg;
}

TEST(Restitution, TU3_Eq11WhereDefined) {
  EXPECT_NEAR(restitution_cg(0.9, cg_of(2, RestitutionPolicy::Energy)).value, 0.78740, 1e-5);
  EXPECT_NEAR(restitution_cg(0.9, cg_of(3, RestitutionPolicy::Energy)).value, 0.65574, 1e-5);
  EXPECT_NEAR(restitution_cg(0.9, cg_of(3, RestitutionPolicy::EnergyClamped)).value, 0.65574, 1e-5);
  EXPECT_TRUE(restitution_cg(0.9, cg_of(3, RestitutionPolicy::Energy)).warning.empty());
}

TEST(Restitution, TU3_PaperValueIsRefusedUnderEnergyPolicy) {
  const RestitutionCg r = restitution_cg(0.1, cg_of(3, RestitutionPolicy::Energy));
  EXPECT_FALSE(r.defined);
  EXPECT_FALSE(std::isnan(r.value));
  EXPECT_NEAR(r.argument, 1.0 + (0.01 - 1.0) * 3.0, 1e-12);  // -1.97
  EXPECT_NE(r.warning.find("no real value"), std::string::npos);
}

TEST(Restitution, TU3_ClampedToFloorWithWarning) {
  const RestitutionCg r = restitution_cg(0.1, cg_of(3, RestitutionPolicy::EnergyClamped, 0.05));
  EXPECT_TRUE(r.clamped);
  EXPECT_DOUBLE_EQ(r.value, 0.05);
  EXPECT_FALSE(r.warning.empty());
  EXPECT_FALSE(std::isnan(r.value));
}

TEST(Restitution, TU3_NoneKeepsInput) {
  const RestitutionCg r = restitution_cg(0.1, cg_of(3, RestitutionPolicy::None));
  EXPECT_DOUBLE_EQ(r.value, 0.1);
  EXPECT_TRUE(r.warning.empty());
}

TEST(Restitution, ZeroRadicandIsRefusedNotNaN) {
  // e = 0.5 at k = 4/3 gives 1 + (e^2 - 1) k = 0 exactly: e_cg = 0 has no finite damping.
  const RestitutionCg r = restitution_cg(0.5, cg_of(4.0 / 3.0, RestitutionPolicy::Energy));
  EXPECT_FALSE(r.defined);
  const RestitutionCg c = restitution_cg(0.5, cg_of(4.0 / 3.0, RestitutionPolicy::EnergyClamped));
  EXPECT_TRUE(c.clamped);
  EXPECT_TRUE(std::isfinite(normal_damping(1e4, 1e-3, c.value)));
}

TEST(Restitution, KMaxBoundary) {
  // Eq. 11 exists only for k <= 1 / (1 - e^2): 5.263 for e = 0.9.
  EXPECT_TRUE(restitution_cg(0.9, cg_of(5.26, RestitutionPolicy::Energy)).defined);
  EXPECT_FALSE(restitution_cg(0.9, cg_of(5.27, RestitutionPolicy::Energy)).defined);
}

TEST(Damping, TU4_ReferenceRow) {
  // L, k = 3, k_n = 1e4 (VERIFICATION.md 1.4): eta_pp = 1.844, t_col,pp = 6.074e-4,
  // eta_pw = 2.607, t_col,pw = 8.589e-4.
  const double m = 4.863e-4 * (1.0 + 0.0);  // CG particle mass, table value
  const double m_pp = effective_mass(m, m), m_pw = effective_mass(m, 0.0);
  EXPECT_NEAR(normal_damping(1e4, m_pp, 0.1), 1.844, 1.844 * 1e-3);
  EXPECT_NEAR(collision_time(1e4, m_pp, 0.1), 6.074e-4, 6.074e-4 * 1e-3);
  EXPECT_NEAR(normal_damping(1e4, m_pw, 0.1), 2.607, 2.607 * 1e-3);
  EXPECT_NEAR(collision_time(1e4, m_pw, 0.1), 8.589e-4, 8.589e-4 * 1e-3);
}

TEST(Damping, TU4_FormulasForUnequalMasses) {
  // eta = 2 sqrt(k m_eff) |ln e| / sqrt(pi^2 + ln^2 e); t_col = pi / sqrt(k/m - eta^2/(4 m^2)).
  const double pi = 3.14159265358979323846;
  for (double e : {0.1, 0.5, 0.9}) {
    const double m1 = 1e-3, m2 = 3e-3, k = 2e4;
    const double m_eff = m1 * m2 / (m1 + m2);
    const double l = std::log(e);
    const double eta = 2.0 * std::sqrt(k * m_eff) * std::fabs(l) / std::sqrt(pi * pi + l * l);
    EXPECT_NEAR(normal_damping(k, effective_mass(m1, m2), e) / eta, 1.0, 1e-9);
    const double t = pi / std::sqrt(k / m_eff - eta * eta / (4.0 * m_eff * m_eff));
    EXPECT_NEAR(collision_time(k, effective_mass(m1, m2), e) / t, 1.0, 1e-9);
    // Same t_col from the damped frequency: e = exp(-eta t_col / (2 m_eff)) (Eq. 9 with E2).
    EXPECT_NEAR(std::exp(-eta * t / (2.0 * m_eff)), e, 1e-9);
  }
  EXPECT_DOUBLE_EQ(effective_mass(2e-3, 0.0), 2e-3);  // wall: m_eff = m (E5)
}

}  // namespace
}  // namespace silodem
