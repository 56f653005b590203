// SPDX-License-Identifier: MIT
// Each contact law alone, on a prescribed contact geometry (no time integration), against its
// equation; and T-C5, the pull-off work of the cohesion range laws.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include <cmath>

#include "../../physics/helpers.hpp"
#include "model/contact/cohesion_common.hpp"
#include "model/contact/dispatch.hpp"

namespace silodem {
namespace {

using test::Laws;

// Two equal spheres (R = 5 mm, m = 1 g) along x with the given overlap and normal approach rate.
ContactGeometry geometry(double overlap, double overlap_rate = 0.0, Vec3 v_t = {}) {
  BodyState i, j;
  i.radius = j.radius = 5e-3;
  i.mass = j.mass = 1e-3;
  i.inertia = j.inertia = 0.4 * 1e-3 * 25e-6;
  i.inv_inertia = j.inv_inertia = 1.0 / i.inertia;
  i.x = {2 * 5e-3 - overlap, 0, 0};
  i.v = Vec3{-overlap_rate, 0, 0} + v_t;
  return pair_geometry(i, j);
}

TEST(Registry, EverySlotHasNoneExceptNormalAndNamesAreUnique) {
  for (Slot s : {Slot::Tangential, Slot::Rolling, Slot::Cohesion})
    EXPECT_NE(find_law(s, "none"), nullptr) << slot_name(s);
  EXPECT_NE(find_law(Slot::Normal, "linear_spring_dashpot"), nullptr);
  for (const auto& a : contact_laws())
    for (const auto& b : contact_laws())
      if (&a != &b) {
        EXPECT_FALSE(a.slot == b.slot && std::string(a.name) == b.name) << a.name;
      }
}

// The force loop runs the kernels dispatch.hpp picks from a law's indices: each registered law
// must select its own compiled kernel (a list out of order would run the wrong physics).
TEST(Dispatch, EachLawSelectsItsOwnCompiledKernel) {
  for (const LawEntry& e : contact_laws()) {
    ContactLaw law;
    law.law_index[static_cast<int>(e.slot)] = e.index;
    const std::string got = with_kernels(law, [&](auto k) -> std::string {
      using K = decltype(k);
      switch (e.slot) {
        case Slot::Normal:
          return K::Normal::name;
        case Slot::Tangential:
          return K::Tangential::name;
        case Slot::Rolling:
          return K::Rolling::name;
        case Slot::Cohesion:
          return K::Cohesion::name;
      }
      return "";
    });
    EXPECT_EQ(got, e.name) << slot_name(e.slot);
  }
}

TEST(Geometry, PairKinematics) {
  const ContactGeometry g = geometry(1e-4, 0.2);
  EXPECT_NEAR(g.overlap, 1e-4, 1e-15);
  EXPECT_NEAR(g.overlap_rate, 0.2, 1e-12);
  EXPECT_NEAR(g.n.x, 1.0, 1e-15);
  EXPECT_NEAR(g.m_eff, 0.5e-3, 1e-15);
  EXPECT_NEAR(g.r_eff, 2.5e-3, 1e-15);
  EXPECT_NEAR(g.arm_i + g.arm_j, 1e-2 - 1e-4, 1e-15);
  // Spin of i about z moves its contact point (at -arm_i x) by omega x r = -arm_i omega y.
  BodyState i, j;
  i.radius = j.radius = 5e-3;
  i.mass = j.mass = 1e-3;
  i.x = {1e-2, 0, 0};
  i.omega = {0, 0, 10.0};
  const ContactGeometry s = pair_geometry(i, j);
  EXPECT_NEAR(s.v_t.y, -10.0 * 5e-3, 1e-12);
}

TEST(NormalLsd, SpringDashpotAndClip) {
  Laws l;
  l.normal_p = {{"stiffness", 2e4}, {"restitution", 0.3}};
  const ContactLaw law = test::law_of(l, false);
  const ContactGeometry g = geometry(1e-4, -0.5);  // separating
  const NormalForce f = test::kernel<NormalLinearSpringDashpot>(law, g, nullptr);
  const double eta = normal_damping(2e4, 0.5e-3, 0.3);
  EXPECT_NEAR(f.elastic, 2.0, 1e-12);
  EXPECT_NEAR(f.damping, -0.5 * eta, 1e-12);
  EXPECT_NEAR(f.total, 2.0 - 0.5 * eta, 1e-12);
  const ContactGeometry fast = geometry(1e-5, -5.0);
  EXPECT_LT(test::kernel<NormalLinearSpringDashpot>(law, fast, nullptr).total,
            0.0);  // MFIX: the dashpot may pull
  l.normal_p["clip_attractive"] = 1;
  const ContactLaw clipped = test::law_of(l, false);
  EXPECT_EQ(test::kernel<NormalLinearSpringDashpot>(clipped, fast, nullptr).total, 0.0);
}

TEST(TangentialHistory, SpringDashpotBelowTheCap) {
  Laws l;
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.5}};
  const ContactLaw law = test::law_of(l, false);
  const ContactGeometry g = geometry(1e-4, 0.0, {0, 0.01, 0});
  double spring[3] = {};
  const double dt = 1e-5, eta_n = 1.0;
  NormalForce fn;  // what the normal law passes on: cap force 100 N, eta_n, k_n
  fn.total = 100.0, fn.eta = eta_n, fn.stiffness = 1e4;
  const Vec3 f = test::kernel<TangentialLinearHistory>(law, g, fn, 0.0, spring, dt);
  const double kt = 2.0 / 7.0 * 1e4;
  EXPECT_NEAR(spring[1], 0.01 * dt, 1e-18);
  EXPECT_NEAR(f.y, -kt * 0.01 * dt - 0.5 * eta_n * 0.01, 1e-12);
}

TEST(TangentialHistory, CoulombCapAndSpringReset) {
  Laws l;
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.3}};
  const ContactLaw law = test::law_of(l, false);
  const ContactGeometry g = geometry(1e-4, 0.0, {0, 0.2, 0});
  double spring[3] = {0, 1e-3, 0};  // far beyond the cap
  NormalForce fn;
  fn.total = 2.0, fn.eta = 0.5, fn.stiffness = 1e4;
  const Vec3 f = test::kernel<TangentialLinearHistory>(law, g, fn, 0.0, spring, 1e-5);
  EXPECT_NEAR(norm(f), 0.3 * 2.0, 1e-12);
  EXPECT_LT(f.y, 0.0);
  // E6: on slip the spring is reset to the cap, k_t |xi| = mu F_n, along the force.
  EXPECT_NEAR(-2.0 / 7.0 * 1e4 * spring[1], f.y, 1e-12);
}

TEST(TangentialHistory, SpringIsRotatedIntoTheNewTangentPlane) {
  Vec3 s{0.3, 1.0, 0.0};
  rotate_into_tangent_plane(s, Vec3{1, 0, 0});
  EXPECT_NEAR(s.x, 0.0, 1e-15);
  EXPECT_NEAR(norm(s), std::sqrt(1.09), 1e-12);
}

TEST(CohesionLaws, ForceVersusGap) {
  const double F = 0.26, d_ref = 1e-2;
  Laws l;
  l.cohesion = "overlap-only";
  ContactLaw law = test::law_of(l, false, F, F);
  EXPECT_EQ(test::kernel<CohesionOverlapOnly>(law, geometry(1e-6), NormalForce{}, nullptr), F);
  EXPECT_EQ(test::kernel<CohesionOverlapOnly>(law, geometry(-1e-9), NormalForce{}, nullptr), 0.0);
  EXPECT_EQ(law.reach_over_d, 0.0);

  l.cohesion = "constant-range";
  l.cohesion_p = {{"range", 0.02}};
  law = test::law_of(l, false, F, F);
  EXPECT_EQ(test::kernel<CohesionConstantRange>(law, geometry(1e-6), NormalForce{}, nullptr), F);
  EXPECT_EQ(
      test::kernel<CohesionConstantRange>(law, geometry(-0.019 * d_ref), NormalForce{}, nullptr),
      F);
  EXPECT_EQ(
      test::kernel<CohesionConstantRange>(law, geometry(-0.021 * d_ref), NormalForce{}, nullptr),
      0.0);

  l.cohesion = "mfix-like";
  l.cohesion_p = {{"inner", 0.001}, {"outer", 0.05}};
  law = test::law_of(l, false, F, F);
  EXPECT_EQ(test::kernel<CohesionMfixLike>(law, geometry(1e-6), NormalForce{}, nullptr), F);
  EXPECT_EQ(test::kernel<CohesionMfixLike>(law, geometry(-0.0005 * d_ref), NormalForce{}, nullptr),
            F);
  EXPECT_NEAR(test::kernel<CohesionMfixLike>(law, geometry(-0.004 * d_ref), NormalForce{}, nullptr),
              F / 16.0, 1e-12);
  EXPECT_EQ(test::kernel<CohesionMfixLike>(law, geometry(-0.051 * d_ref), NormalForce{}, nullptr),
            0.0);
  EXPECT_EQ(law.reach_over_d, 0.05);
}

TEST(CohesionLaws, PairRulesAndWallFactor) {
  EXPECT_DOUBLE_EQ(cohesion_pair_rule("mean", 0.2, 0.4), 0.3);
  EXPECT_DOUBLE_EQ(cohesion_pair_rule("min", 0.2, 0.4), 0.2);
  EXPECT_NEAR(cohesion_pair_rule("harmonic", 0.2, 0.4), 2 * 0.08 / 0.6, 1e-15);
  Laws l;
  l.cohesion = "overlap-only";
  l.cohesion_s = {{"pair_rule", "min"}};
  EXPECT_DOUBLE_EQ(test::cohesion_force(test::law_of(l, false, 0.26, 0.417)), 0.26);
  l.cohesion_s.clear();
  l.cohesion_p = {{"wall_factor", 0.5}};
  EXPECT_DOUBLE_EQ(test::cohesion_force(test::law_of(l, true, 0.26)), 0.13);
  l.cohesion_p = {{"wall_factor", 0.5}, {"factor", 0.1}};
  EXPECT_DOUBLE_EQ(test::cohesion_force(test::law_of(l, true, 0.26)), 0.013);
  l.cohesion_p = {{"factor", 0.1}};
  EXPECT_DOUBLE_EQ(test::cohesion_force(test::law_of(l, false, 0.2, 0.4)), 0.1 * 0.3);
}

// Quasi-static pull-off work W = integral of the net attractive force from the bonded
// equilibrium (k_n delta = F) to where the force vanishes, evaluated through evaluate_contact.
double pull_off_work(const ContactLaw& law) {
  ContactState s;
  const double d_ref = 1e-2;
  double w = 0.0;
  const double delta_eq = test::cohesion_force(law) / test::normal_stiffness(law);
  const double end = law.reach_over_d * d_ref + 1e-9;
  const int n = 400000;
  const double h = (delta_eq + end) / n;
  for (int k = 0; k < n; ++k) {
    const double overlap = delta_eq - (k + 0.5) * h;  // midpoint rule
    const ContactResult r = evaluate_contact(law, geometry(overlap), s, 1e-6);
    w += -r.force_i.x * h;  // force on i along +x (separation direction) is -pull
  }
  return w;
}

TEST(CohesionLaws, TC5_PullOffWorkOfRangeLaws) {
  const double F = 0.2599;
  const double d = 1e-2;
  for (double kn : {1e3, 1e4, 1e5}) {
    Laws l;
    l.normal_p = {{"stiffness", kn}, {"restitution", 0.1}};
    l.cohesion = "overlap-only";
    EXPECT_NEAR(pull_off_work(test::law_of(l, false, F, F)) / (F * F / (2 * kn)), 1.0, 0.02);
    l.cohesion = "constant-range";
    l.cohesion_p = {{"range", 0.02}};
    const double w_range = F * 0.02 * d + F * F / (2 * kn);
    EXPECT_NEAR(pull_off_work(test::law_of(l, false, F, F)) / w_range, 1.0, 0.02) << kn;
    l.cohesion = "mfix-like";
    l.cohesion_p = {{"inner", 0.002}, {"outer", 0.02}};
    const double s_in = 0.002 * d, s_out = 0.02 * d;
    const double w_mfix = F * s_in + F * s_in * s_in * (1 / s_in - 1 / s_out) + F * F / (2 * kn);
    EXPECT_NEAR(pull_off_work(test::law_of(l, false, F, F)) / w_mfix, 1.0, 0.02) << kn;
  }
}

TEST(RollingEpsd, LimitTorqueAndOppositeOnPartner) {
  Laws l;
  l.rolling = "epsd";
  l.rolling_p = {{"friction", 0.2}};
  const ContactLaw law = test::law_of(l, false);
  ContactGeometry g = geometry(1e-4);
  g.omega_i = {0, 100.0, 0};
  NormalForce fn;
  fn.total = 1.0;
  fn.stiffness = 1e4;
  double spring[3] = {};
  const RollingTorque t = test::kernel<RollingEpsd>(law, g, fn, 0.0, spring, 1e-3);
  // saturated at mu_r R_eff |F_n|
  EXPECT_NEAR(norm(Vec3{spring[0], spring[1], spring[2]}), 0.2 * g.r_eff * 1.0, 1e-15);
  EXPECT_LT(t.on_i.y, 0.0);
  EXPECT_NEAR(t.on_j.y, -t.on_i.y, 1e-18);
}

// Two particles that cannot rotate (inv_inertia 0, infinite inertia: both glued to a shear cell's
// plate) get a finite torque below the limit: the rolling damping has nothing to damp, where
// infinity x 0 gave NaN.
TEST(RollingEpsd, BodiesThatCannotRotateGetAFiniteTorque) {
  Laws l;
  l.rolling = "epsd";
  l.rolling_p = {{"friction", 0.2}};
  const ContactLaw law = test::law_of(l, false);
  ContactGeometry g = geometry(1e-4);
  g.inertia_i = g.inertia_j = std::numeric_limits<double>::infinity();
  NormalForce fn;
  fn.total = 1.0;
  fn.stiffness = 1e4;
  double spring[3] = {1e-6, 0, 0};  // below the limit 0.2 R_eff 1 N
  const RollingTorque t = test::kernel<RollingEpsd>(law, g, fn, 0.0, spring, 1e-3);
  EXPECT_TRUE(std::isfinite(t.on_i.x) && std::isfinite(t.on_i.y) && std::isfinite(t.on_i.z));
  EXPECT_DOUBLE_EQ(t.on_i.x, 1e-6);  // the spring alone (omega = 0: it does not change)
}

TEST(SeesCohesion, TensionGivesNoFrictionOrRollingCapacity) {
  // A bond pulled apart (contact force 0.05 N < cohesion 0.1 N): with the switches on, the net
  // normal force is tensile and the Coulomb cap and rolling limit are zero, not |F_n - F_coh|.
  Laws l;
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.5}, {"cap_sees_cohesion", 1.0}};
  l.rolling = "epsd";
  l.rolling_p = {{"friction", 0.2}, {"limit_sees_cohesion", 1.0}};
  l.cohesion = "overlap-only";
  l.normal_p = {{"stiffness", 500.0}, {"restitution", 0.5}};
  const ContactLaw law = test::law_of(l, false, 0.1, 0.1);
  ContactGeometry g = geometry(1e-4, 0.0, {0, 0.01, 0});  // k_n delta = 0.05 N
  g.omega_i = {0, 50.0, 0};
  ContactState s;
  const ContactResult r = evaluate_contact(law, g, s, 1e-4);
  EXPECT_NEAR(r.force_i.y, 0.0, 1e-15);
  EXPECT_NEAR(norm(s.vec(law.layout.offset[int(Slot::Rolling)])), 0.0, 1e-15);
}

TEST(RollingMfix, TorqueOpposesOwnSpinWithDiameter) {
  Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.rolling = "mfix";
  l.rolling_p = {{"friction", 0.6}, {"regularize", 0.0}};
  const ContactLaw law = test::law_of(l, false);
  ContactGeometry g = geometry(1e-4);
  g.omega_i = {0, 0, 3.0};
  g.omega_j = {2.0, 0, 0};
  const RollingTorque t =
      test::kernel<RollingMfix>(law, g, test::normal_force(law, g), 0.0, nullptr, 1e-5);
  const double mag = 0.6 * 1e-2 * 1e4 * 1e-4;  // mu_r d k_n delta_n
  EXPECT_NEAR(t.on_i.z, -mag, 1e-15);
  EXPECT_NEAR(t.on_j.x, -mag, 1e-15);
}

TEST(RollingMfix, RegularizedOnlyBelowTenStepsOfSpin) {
  Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.rolling = "mfix";
  l.rolling_p = {{"friction", 0.6}};
  const ContactLaw law = test::law_of(l, false);
  ContactGeometry g = geometry(1e-4);
  const double mag = 0.6 * 1e-2 * 1e4 * 1e-4, dt = 1e-5;
  const double w_eps = 10 * mag * dt / g.inertia_i;  // 6 rad/s here
  g.omega_i = {0, 0, 2 * w_eps};                     // rolling: exactly MFIX
  EXPECT_NEAR(
      test::kernel<RollingMfix>(law, g, test::normal_force(law, g), 0.0, nullptr, dt).on_i.z, -mag,
      1e-15);
  g.omega_i = {0, 0, 0.25 * w_eps};  // nearly at rest: a viscous stop
  EXPECT_NEAR(
      test::kernel<RollingMfix>(law, g, test::normal_force(law, g), 0.0, nullptr, dt).on_i.z,
      -0.25 * mag, 1e-15);
}

// MFiX 21.3's form with L = mu_r d is MFiX 25.x's (`mfix`): the same torque on both particles,
// at rest, rolling (|omega| > w_eps) and in the regularized stop, with and without `regularize`.
TEST(RollingMfix21, SameTorqueAsMfixWhenLengthIsMuRTimesD) {
  const double mu_r = 0.6, d = 1e-2, dt = 1e-5;
  for (bool regularize : {true, false}) {
    Laws mfix, mfix21;
    mfix.rolling = "mfix";
    mfix.rolling_p = {{"friction", mu_r}, {"regularize", regularize ? 1.0 : 0.0}};
    mfix21.rolling = "mfix-21";
    mfix21.rolling_p = {{"length_m", mu_r * d}, {"regularize", regularize ? 1.0 : 0.0}};
    const ContactLaw a = test::law_of(mfix, false), b = test::law_of(mfix21, false);
    ContactGeometry g = geometry(1e-4);
    const double w_eps = 10 * mu_r * d * 1e4 * 1e-4 * dt / g.inertia_i;  // 6 rad/s
    for (double w : {0.0, 0.25 * w_eps, 2 * w_eps, 300.0}) {
      g.omega_i = {0.6 * w, 0, -0.8 * w};
      g.omega_j = {0, w, 0};
      const RollingTorque ta =
          test::kernel<RollingMfix>(a, g, test::normal_force(a, g), 0.0, nullptr, dt);
      const RollingTorque tb =
          test::kernel<RollingMfix21>(b, g, test::normal_force(b, g), 0.0, nullptr, dt);
      if (w > 0.0) {
        EXPECT_GT(norm(ta.on_i), 0.0);  // the comparison is not 0 = 0
      }
      EXPECT_NEAR(norm(tb.on_i - ta.on_i), 0.0, 1e-16) << w << " " << regularize;
      EXPECT_NEAR(norm(tb.on_j - ta.on_j), 0.0, 1e-16) << w << " " << regularize;
    }
  }
}

TEST(RollingMfix21, NoLeverArmSameTorqueOnUnequalSpheres) {
  // R_i = 5 mm, R_j = 10 mm: MFiX 21.3 applies L k_n delta_n to both; `mfix` would apply
  // mu_r d_i and mu_r d_j, 1:2.
  Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.rolling = "mfix-21";
  l.rolling_p = {{"length_m", 0.6}, {"regularize", 0.0}};
  const ContactLaw law = test::law_of(l, false);
  BodyState i, j;
  i.radius = 5e-3, j.radius = 10e-3;
  i.mass = 1e-3, j.mass = 8e-3;
  i.inertia = 0.4 * i.mass * 25e-6, j.inertia = 0.4 * j.mass * 100e-6;
  i.inv_inertia = 1 / i.inertia, j.inv_inertia = 1 / j.inertia;
  i.x = {15e-3 - 1e-4, 0, 0};
  i.omega = {0, 0, 3.0};
  j.omega = {-2.0, 0, 0};
  const ContactGeometry g = pair_geometry(i, j);
  const RollingTorque t =
      test::kernel<RollingMfix21>(law, g, test::normal_force(law, g), 0.0, nullptr, 1e-5);
  const double mag = 0.6 * 1e4 * 1e-4;  // L k_n delta_n = 0.6 N m
  EXPECT_NEAR(t.on_i.z, -mag, 1e-12);
  EXPECT_NEAR(t.on_j.x, mag, 1e-12);
  EXPECT_NEAR(norm(t.on_i), mag, 1e-12);
  EXPECT_NEAR(norm(t.on_j), mag, 1e-12);
  // Against a wall: i only.
  const ContactLaw wall = test::law_of(l, true);
  const ContactGeometry gw = wall_geometry(i, {1, 0, 0}, 5e-3 - 1e-4, {});
  const RollingTorque tw =
      test::kernel<RollingMfix21>(wall, gw, test::normal_force(wall, gw), 0.0, nullptr, 1e-5);
  EXPECT_NEAR(tw.on_i.z, -mag, 1e-12);
  EXPECT_EQ(norm(tw.on_j), 0.0);
}

TEST(RollingMfix21, RegularizedStopIsTheSameViscousCoefficientForAnyLength) {
  // w_eps = 10 T dt / I grows with T = L k_n delta_n, so below it the torque is -I omega/(10 dt)
  // for every L: the coefficient of the stability argument (rolling_mfix.hpp) does not grow with
  // the paper's 0.6 read as metres. At 2 w_eps the torque is MFiX's, -T.
  const double dt = 1e-5;
  for (double length : {6e-3, 0.6}) {
    Laws l;
    l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
    l.rolling = "mfix-21";
    l.rolling_p = {{"length_m", length}};
    const ContactLaw law = test::law_of(l, false);
    ContactGeometry g = geometry(1e-4);
    const double mag = length * 1e4 * 1e-4, w_eps = 10 * mag * dt / g.inertia_i;
    g.omega_i = {0, 0, 2 * w_eps};
    EXPECT_NEAR(
        test::kernel<RollingMfix21>(law, g, test::normal_force(law, g), 0.0, nullptr, dt).on_i.z /
            -mag,
        1.0, 1e-12);
    g.omega_i = {0, 0, 0.25 * w_eps};
    const double c =
        -test::kernel<RollingMfix21>(law, g, test::normal_force(law, g), 0.0, nullptr, dt).on_i.z /
        g.omega_i.z;
    EXPECT_NEAR(c / (g.inertia_i / (10 * dt)), 1.0, 1e-12) << length;
  }
}

TEST(ContactModel, NoTouchClearsHistoryAndRangedCohesionStillPulls) {
  Laws l;
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.3}};
  l.cohesion = "constant-range";
  l.cohesion_p = {{"range", 0.05}};
  const ContactLaw law = test::law_of(l, false, 0.1, 0.1);
  ContactState s;
  s.h[1] = 1e-6;  // the tangential spring (the first law with a history)
  const ContactResult r = evaluate_contact(law, geometry(-1e-4), s, 1e-5);
  EXPECT_FALSE(r.touching);
  EXPECT_EQ(norm2(s.vec(0)), 0.0);
  EXPECT_NEAR(r.force_i.x, -0.1, 1e-15);  // pulls i towards j
}

// ---- Luding's elasto-plastic adhesive law (normal_luding.hpp; Luding 2008, Eq. 3-6) ----------
Laws luding(double phi_f = 0.0, double scale = 1.0) {
  Laws l;
  l.normal = "luding";
  l.normal_p = {{"stiffness", 1e3 * scale},
                {"unloading_stiffness", 5e3 * scale},
                {"adhesion_stiffness", 2e3 * scale},
                {"plastic_depth", phi_f},
                {"restitution", 0.5}};
  return l;
}

// The elastic part of the normal force along a path of overlaps, the history carried.
std::vector<double> luding_path(const ContactLaw& law, const std::vector<double>& overlaps,
                                double* delta_max = nullptr) {
  ContactState s;
  std::vector<double> f;
  for (double o : overlaps) f.push_back(test::normal_force_with(law, geometry(o), s).elastic);
  if (delta_max) *delta_max = s.h[0];
  return f;
}

TEST(NormalLuding, LoadingUnloadingAndTheAdhesiveLimit) {
  const ContactLaw law = test::law_of(luding(), false);
  const double k1 = 1e3, k2 = 5e3, kc = 2e3, dmax = 1e-4;
  const double d0 = (1 - k1 / k2) * dmax;            // 0.8e-4: force-free after unloading
  const double dmin = (k2 - k1) / (k2 + kc) * dmax;  // where the pull is largest
  std::vector<double> path;
  for (int k = 1; k <= 1000; ++k) path.push_back(dmax * k / 1000);        // load on k1
  for (int k = 999; k >= 1; --k) path.push_back(dmax * k / 1000 + 1e-9);  // unload
  double after = 0;
  const std::vector<double> f = luding_path(law, path, &after);
  auto at = [&](int k) { return path[std::size_t(k)]; };
  EXPECT_NEAR(f[999], k1 * dmax, 1e-12);              // the top of the loading line
  EXPECT_NEAR(f[1099], k2 * (at(1099) - d0), 1e-12);  // unloading on the slope k2
  EXPECT_NEAR(f[1199], k2 * (at(1199) - d0), 1e-12);  // force-free at delta0 = 0.8 dmax
  EXPECT_NEAR(f[1199], 0.0, 1e-5);
  EXPECT_NEAR(f[1799], -kc * at(1799), 1e-12);  // 0.2 dmax: on the adhesive limit
  double pull = 0;
  for (double x : f) pull = std::min(pull, x);
  // The largest pull, at delta_min = 4/7 dmax, within the path's sampling (dmax / 1000).
  EXPECT_GE(pull, -kc * dmin - 1e-12);
  EXPECT_NEAR(pull, -kc * dmin, 0.005 * kc * dmin);
  // On the adhesive limit delta_max follows the overlap: (k2 + kc) / (k2 - k1) delta.
  EXPECT_NEAR(after / ((k2 + kc) / (k2 - k1) * path.back()), 1.0, 1e-9);  // geometry rounding
}

TEST(NormalLuding, PullOffIsAFixedFractionOfTheLargestLoad) {
  // Press with F_max on the loading branch, then unload slowly to the end: the largest pull is
  // kc (k2 - k1) / ((k2 + kc) k1) F_max (Luding 2008, Eq. 6).
  const ContactLaw law = test::law_of(luding(), false);
  const double k1 = 1e3, k2 = 5e3, kc = 2e3, lambda = kc * (k2 - k1) / ((k2 + kc) * k1);
  for (double f_max : {0.05, 0.1, 0.4}) {
    std::vector<double> path;
    const double dmax = f_max / k1;
    for (int k = 1; k <= 100; ++k) path.push_back(dmax * k / 100);
    for (int k = 999; k >= 1; --k) path.push_back(dmax * k / 1000);
    double pull = 0;
    for (double x : luding_path(law, path)) pull = std::min(pull, x);
    EXPECT_NEAR(-pull / (lambda * f_max), 1.0, 0.01) << f_max;
  }
}

TEST(NormalLuding, StrengthUnderOneStressIsTheSameForEveryK) {
  // The CG rule of docs/models/normal_luding.md: stiffnesses in proportion to the diameter. A
  // contact of CG spheres k times larger, consolidated at the same stress (F_max = sigma d^2),
  // then has the same strength f_pull / d^2, also with a plastic depth (k2 depends on
  // delta_max / d). Without the rule (the same stiffnesses for every k) it does not.
  const double sigma = 2e3, d0 = 1e-2;  // Pa; the geometry's spheres, d = 1 cm
  auto strength = [&](double k, bool scaled) {
    const ContactLaw law = test::law_of(luding(0.05, scaled ? k : 1.0), false);
    BodyState i, j;
    i.radius = j.radius = 0.5 * k * d0;
    i.mass = j.mass = 1e-3 * k * k * k;
    i.inertia = j.inertia = 0.4 * i.mass * i.radius * i.radius;
    i.inv_inertia = j.inv_inertia = 1.0 / i.inertia;
    const double f_max = sigma * (k * d0) * (k * d0);
    ContactState s;
    // Load to f_max along the loading line f = k1 delta, then unload to the end.
    const double k1 = 1e3 * (scaled ? k : 1.0), dmax = f_max / k1;
    double pull = 0;
    for (int step = 1; step <= 2000; ++step) {
      const double o = step <= 1000 ? dmax * step / 1000 : dmax * (2000 - step + 0.5) / 1000;
      i.x = {2 * i.radius - o, 0, 0};
      pull = std::min(pull, test::normal_force_with(law, pair_geometry(i, j), s).elastic);
    }
    return -pull / ((k * d0) * (k * d0));
  };
  const double base = strength(1, true);
  EXPECT_GT(base, 0.0);
  for (double k : {2.0, 3.0, 4.0}) EXPECT_NEAR(strength(k, true) / base, 1.0, 1e-3) << k;
  EXPECT_GT(std::fabs(strength(4, false) / base - 1.0), 0.05);  // the rule matters
}

TEST(NormalLuding, HistoryLivesAsLongAsTheContact) {
  const ContactLaw law = test::law_of(luding(), false);
  ASSERT_EQ(law.layout.size, 1);
  EXPECT_EQ(law.layout.swap[0], 1.0);  // a scalar: the same seen from i or from j
  ContactState s;
  const ContactGeometry pressed = geometry(1e-4);
  evaluate_contact(law, pressed, s, 1e-6);
  EXPECT_EQ(s.h[0], pressed.overlap);
  evaluate_contact(law, geometry(0.9e-4), s, 1e-6);  // k2 (delta - delta0) = 0.05 N: unloading
  EXPECT_EQ(s.h[0], pressed.overlap);                // keeps the largest overlap
  evaluate_contact(law, geometry(-1e-6), s, 1e-6);
  EXPECT_EQ(s.h[0], 0.0);  // separated: a new contact starts fresh
}

// A Luding contact on its adhesive branch pulls (elastic force < 0). MFIX's rolling torque has the
// size mu_r d |k_n delta| and must still oppose each particle's spin: with the signed force it
// pushed the spin on, a constant torque that spun parcels held by adhesion up without bound.
TEST(NormalLuding, MfixRollingTorqueOpposesTheSpinOfAContactInTension) {
  for (const char* rolling : {"mfix", "mfix-21"}) {
    SCOPED_TRACE(rolling);
    Laws l = luding();
    l.rolling = rolling;
    if (std::string(rolling) == "mfix")
      l.rolling_p = {{"friction", 0.6}, {"regularize", 0.0}};
    else
      l.rolling_p = {{"length_m", 6e-3}, {"regularize", 0.0}};  // = 0.6 d
    const ContactLaw law = test::law_of(l, false);
    ContactState s;
    test::normal_force_with(law, geometry(1e-4), s);  // loaded to delta_max on k1
    ContactGeometry g = geometry(0.2e-4);             // unloaded onto the adhesive limit
    g.omega_i = {0, 0, 3.0};
    g.omega_j = {2.0, 0, 0};
    const NormalForce fn = test::normal_force_with(law, g, s);
    ASSERT_NEAR(fn.elastic, -2e3 * 0.2e-4, 1e-12);  // -kc delta: a pull
    const RollingTorque t = std::string(rolling) == "mfix"
                                ? test::kernel<RollingMfix>(law, g, fn, 0.0, nullptr, 1e-5)
                                : test::kernel<RollingMfix21>(law, g, fn, 0.0, nullptr, 1e-5);
    const double mag = 0.6 * 1e-2 * std::fabs(fn.elastic);
    EXPECT_NEAR(t.on_i.z, -mag, 1e-15);  // against omega_i = +z
    EXPECT_NEAR(t.on_j.x, -mag, 1e-15);  // against omega_j = +x
  }
}

// Luding's rule for the friction and rolling limits of his adhesive law (as WooDEM implements it):
// mu (F_n + kc delta), the normal force with the law's own pull added back, instead of mu |F_n|.
// On the loading branch the cap grows by kc delta; on the adhesive limit it is zero, where |F_n|
// gives mu kc delta.
TEST(NormalLuding, CapsAddTheAdhesivePullBackWhenAsked) {
  const double k1 = 1e3, kc = 2e3, mu = 0.5, mu_r = 0.2, dt = 1e-5;
  for (const bool luding_rule : {false, true}) {
    SCOPED_TRACE(luding_rule);
    Laws l = luding();
    l.tangential = "linear_history";
    l.tangential_p = {{"friction", mu}, {"cap_adds_adhesion", luding_rule ? 1.0 : 0.0}};
    l.rolling = "epsd";
    l.rolling_p = {{"friction", mu_r}, {"limit_adds_adhesion", luding_rule ? 1.0 : 0.0}};
    const ContactLaw law = test::law_of(l, false);
    const int at_t = law.layout.offset[int(Slot::Tangential)];
    const int at_r = law.layout.offset[int(Slot::Rolling)];
    // A sliding, rolling contact: the spring far beyond either cap after one step.
    auto slide = [&](double overlap, ContactState& s) {
      ContactGeometry g = geometry(overlap, 0.0, {0, 100.0, 0});
      g.omega_i = {0, 0, 1e5};
      const ContactResult r = evaluate_contact(law, g, s, dt);
      return std::pair{std::fabs(r.force_i.y), norm(s.vec(at_r))};
    };
    ContactState s;
    const double loaded = 1e-4;  // first loading: F_n = k1 delta
    auto [ft, mr] = slide(loaded, s);
    const double r_eff = 2.5e-3;
    const double n_load = luding_rule ? (k1 + kc) * loaded : k1 * loaded;
    EXPECT_NEAR(ft, mu * n_load, 1e-12);
    EXPECT_NEAR(mr, mu_r * r_eff * n_load, 1e-12);
    s.set_vec(at_t, {}), s.set_vec(at_r, {});
    const double pulled = 0.2e-4;  // unloaded onto the adhesive limit: F_n = -kc delta
    std::tie(ft, mr) = slide(pulled, s);
    const double n_pull = luding_rule ? 0.0 : kc * pulled;
    EXPECT_NEAR(ft, mu * n_pull, 1e-12);
    EXPECT_NEAR(mr, mu_r * r_eff * n_pull, 1e-12);
  }
  Laws both = luding();
  both.tangential = "linear_history";
  both.tangential_p = {{"friction", mu}, {"cap_adds_adhesion", 1.0}, {"cap_sees_cohesion", 1.0}};
  EXPECT_THROW(test::law_of(both, false), InputError);
}

}  // namespace
}  // namespace silodem
