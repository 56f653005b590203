// SPDX-License-Identifier: MIT
// Cohesion in motion (VERIFICATION.md 4.3): T-C1 pull-off at F_L,cg independent of k_n (pairs and
// walls), T-C2 capture velocity for overlap-only cohesion, T-C3 a hanging chain, T-C4 the
// friction switch.
#include <gtest/gtest.h>

#include <cmath>

#include "helpers.hpp"

namespace silodem {
namespace {

constexpr double kFL = 0.2599;  // F_L,cg of Longwanggou at k = 3 (N)
constexpr double kR = 4.2e-3;   // k = 3 CG radius (m)
const double kM = test::sphere_mass_of(2 * kR, 1567);

test::Laws cohesive(double kn, double e = 0.1) {
  test::Laws l;
  l.normal_p = {{"stiffness", kn}, {"restitution", e}};
  l.cohesion = "overlap-only";
  return l;
}

// Two particles of radius kR and mass kM along x (or one on the plane x = 0) overlapping by
// `overlap`, without gravity, on one thread, at dt = t_col / 50 of the pair (or wall) contact.
struct TwoBodies {
  std::unique_ptr<Simulation> sim;
  double t_col = 0.0;
  bool wall = false;
  // Forces +f on the bodies apart (f < 0 presses them together).
  void pull(double f) {
    auto& q = sim->particles();
    q.f_ext[0] = {wall ? f : -f, 0, 0};
    if (!wall) q.f_ext[1] = {f, 0, 0};
  }
  double overlap() const {
    const auto& p = sim->particles();
    return wall ? kR - p.x[0].x : 2 * kR - (p.x[1].x - p.x[0].x);
  }
};
TwoBodies two_bodies(ContactModel model, bool wall, double overlap) {
  TwoBodies b;
  b.wall = wall;
  b.t_col =
      wall ? model.wall_collision_time(0, kM, kR) : model.pair_collision_time(0, 0, kM, kM, kR, kR);
  SimulationSettings s;
  s.dt = b.t_col / 50.0;
  s.gravity = {};
  s.threads = 1;
  b.sim = std::make_unique<Simulation>(std::move(model), s);
  auto& p = b.sim->particles();
  if (wall) {
    b.sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
    p.add({kR - overlap, 0, 0}, {}, {}, kR, kM, 0);
  } else {
    p.add({0, 0, 0}, {}, {}, kR, kM, 0);
    p.add({2 * kR - overlap, 0, 0}, {}, {}, kR, kM, 0);
  }
  return b;
}

// Two bonded particles (or one bonded to a wall) pulled apart by +-P, ramped over 200 t_col and
// held for 200 t_col. Returns the final overlap (< 0: separated).
double pull_apart(double kn, double p_over_f, bool wall) {
  TwoBodies b = two_bodies(test::model_of(cohesive(kn), {kFL}), wall, kFL / kn);
  const double target = p_over_f * kFL, ramp = 200 * b.t_col;
  b.sim->add_hook({"pull", Phase::StepBegin, 1,
                   [&](Simulation& sm) { b.pull(target * std::min(1.0, sm.time() / ramp)); }});
  b.sim->run_until(ramp + 200 * b.t_col);
  return b.overlap();
}

TEST(Cohesion, TC1_PullOffIsFLIndependentOfStiffness) {
  for (bool wall : {false, true}) {
    for (double kn : {1e3, 1e4, 1e5}) {
      // Below the pull-off force the pair holds at delta_eq = (F_L - P) / k_n.
      const double ov = pull_apart(kn, 0.98, wall);
      EXPECT_NEAR(ov / ((kFL - 0.98 * kFL) / kn), 1.0, 0.01) << kn << (wall ? " wall" : " pair");
      EXPECT_LT(pull_apart(kn, 1.02, wall), 0.0) << kn << (wall ? " wall" : " pair");
      // Bisection of the threshold.
      double lo = 0.9, hi = 1.1;
      for (int it = 0; it < 6; ++it) {
        const double mid = 0.5 * (lo + hi);
        (pull_apart(kn, mid, wall) > 0.0 ? lo : hi) = mid;
      }
      EXPECT_NEAR(0.5 * (lo + hi), 1.0, 0.01) << kn << (wall ? " wall" : " pair");
    }
  }
}

// Head-on impact at v_in of two equal bonded-to-be particles: true if they stay together.
bool captured(double kn, double e, double v_in) {
  ContactModel model = test::model_of(cohesive(kn, e), {kFL});
  const double t_col = model.pair_collision_time(0, 0, kM, kM, kR, kR);
  SimulationSettings s;
  s.dt = t_col / 100.0;
  s.gravity = {};
  s.threads = 1;
  Simulation sim(std::move(model), s);
  auto& p = sim.particles();
  p.add({0, 0, 0}, {0.5 * v_in, 0, 0}, {}, kR, kM, 0);
  p.add({2 * kR + 1e-6, 0, 0}, {-0.5 * v_in, 0, 0}, {}, kR, kM, 0);
  sim.run_until(1e-6 / v_in + 30 * t_col);
  return 2 * kR - (p.x[1].x - p.x[0].x) > 0.0;
}

TEST(Cohesion, TC2_CaptureVelocityOverlapOnly) {
  // v_crit = f(e) F / sqrt(k_n m_eff) (VERIFICATION.md 1.7 / E12).
  const double kn = 1e4, m_eff = 0.5 * kM;
  const std::pair<double, double> table[] = {{0.1, 21.09}, {0.5, 2.955}, {0.9, 0.713}};
  for (const auto& [e, f] : table) {
    const double v_crit = f * kFL / std::sqrt(kn * m_eff);
    EXPECT_TRUE(captured(kn, e, 0.97 * v_crit)) << "e = " << e;
    EXPECT_FALSE(captured(kn, e, 1.03 * v_crit)) << "e = " << e;
  }
}

// A vertical chain of n particles hanging from a ceiling, gravity ramped from 0 to g over
// 400 t_col then held. Returns true if every bond (wall and particle) still holds.
bool chain_holds(int n, double k, double alpha) {
  const double bo = 10.5, d = 2e-3, rho = 1500;
  const double m1 = test::sphere_mass_of(d, rho);
  const double f_l = bo * m1 * 9.81;  // original-particle force tuned to Bo = 10.5
  CoarseGraining cg;
  cg.k = k;
  cg.cohesion_exponent = alpha;
  const double f_cg = cg.cohesion_force(f_l), m = cg.mass(m1), r = 0.5 * cg.diameter(d);
  const double kn = 2e4 * k;
  ContactModel model = test::model_of(cohesive(kn, 0.3), {f_cg}, nullptr, cg);
  const double t_col = model.pair_collision_time(0, 0, m, m, r, r);
  SimulationSettings s;
  s.dt = t_col / 50.0;
  s.gravity = {};
  s.threads = 1;
  Simulation sim(std::move(model), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, -1}));
  const double d_eq = f_cg / kn;
  for (int i = 0; i < n; ++i)
    sim.particles().add({0, 0, -r + d_eq - i * (2 * r - d_eq)}, {}, {}, r, m, 0);
  const double ramp = 400 * t_col;
  sim.add_hook({"gravity", Phase::StepBegin, 1, [&](Simulation& sm) {
                  sm.set_gravity({0, 0, -9.81 * std::min(1.0, sm.time() / ramp)});
                }});
  sim.run_until(ramp + 400 * t_col);
  const auto& p = sim.particles();
  bool ok = p.x[0].z + r > 0.0;  // still touching the ceiling
  for (int i = 1; i < n; ++i) ok = ok && norm(p.x[i] - p.x[i - 1]) < 2 * r;
  return ok;
}

TEST(Cohesion, TC3_HangingChainHoldsFloorBond) {
  for (double k : {1.0, 2.0, 3.0}) {
    EXPECT_TRUE(chain_holds(10, k, 3.0)) << "k = " << k;
    EXPECT_FALSE(chain_holds(11, k, 3.0)) << "k = " << k;
  }
  // alpha = 2: N_max = floor(Bo / k): 5 at k = 2, 3 at k = 3.
  EXPECT_TRUE(chain_holds(5, 2.0, 2.0));
  EXPECT_FALSE(chain_holds(6, 2.0, 2.0));
  EXPECT_TRUE(chain_holds(3, 3.0, 2.0));
  EXPECT_FALSE(chain_holds(4, 3.0, 2.0));
}

// A particle bonded to a wall by cohesion only (no gravity, no rotation), pulled along the wall by
// a slowly ramped force. Returns the pull at which it starts to slide, / F_L.
double slip_force(bool cap_sees_cohesion) {
  test::Laws l = cohesive(1e4);
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.3}, {"cap_sees_cohesion", cap_sees_cohesion ? 1.0 : 0.0}};
  ContactModel model = test::model_of(l, {kFL});
  const double t_col = model.wall_collision_time(0, kM, kR);
  SimulationSettings s;
  s.dt = t_col / 50.0;
  s.gravity = {};
  s.threads = 1;
  Simulation sim(std::move(model), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  auto& p = sim.particles();
  p.add({0, 0, kR - kFL / 1e4}, {}, {}, kR, kM, 0);
  p.inv_inertia[0] = 0.0;  // no rolling: the contact can only stick or slide
  const double rate = 0.5 * kFL / (2000 * t_col);  // reaches 0.5 F_L after 2000 t_col
  while (sim.time() < 4000 * t_col) {
    p.f_ext[0] = {rate * sim.time(), 0, 0};
    sim.step();
    if (p.v[0].x > 1e-3) return p.f_ext[0].x / kFL;
  }
  return 1e9;
}

TEST(Cohesion, TC4_FrictionSwitch) {
  // MFIX convention: the elastic force k_n delta_eq = F_L loads the Coulomb cap -> mu F_L.
  EXPECT_NEAR(slip_force(false) / 0.3, 1.0, 0.02);
  // Net normal force (elastic + damping - cohesive) is ~0 for an unloaded bond -> slides at once.
  EXPECT_LT(slip_force(true), 0.02);
}

// Luding's law through the engine (normal_luding.hpp): a pair (or a particle on a wall) pressed
// together with F, then pulled with P, both ramped slowly. The largest overlap is the contact's
// history, kept in the neighbour list from step to step; the contact holds while P is below
// lambda F = kc (k2 - k1) / ((k2 + kc) k1) F (Luding 2008, Eq. 6) and lets go above it.
double luding_press_and_pull(double press, double pull, bool wall) {
  test::Laws l;
  l.normal = "luding";
  l.normal_p = {{"stiffness", 1e3},
                {"unloading_stiffness", 5e3},
                {"adhesion_stiffness", 2e3},
                {"restitution", 0.3}};
  TwoBodies b = two_bodies(test::model_of(l), wall, 0.0);
  const double ramp = 200 * b.t_col;  // press: ramp and hold; then to -pull: ramp and hold
  b.sim->add_hook({"press and pull", Phase::StepBegin, 1, [&](Simulation& sm) {
                     const double t = sm.time();
                     const double f = t < 2 * ramp ? press * std::min(1.0, t / ramp)
                                      : t < 3 * ramp
                                          ? press - (press + pull) * (t - 2 * ramp) / ramp
                                          : -pull;
                     b.pull(-f);  // f > 0 presses
                   }});
  b.sim->run_until(5 * ramp);
  return b.overlap();
}

TEST(Cohesion, LudingContactHoldsUpToTheFractionOfTheLoadItCarried) {
  const double lambda = 2e3 * (5e3 - 1e3) / ((5e3 + 2e3) * 1e3);  // 8/7
  for (bool wall : {false, true}) {
    for (double press : {0.1, 0.4}) {
      EXPECT_GT(luding_press_and_pull(press, 0.95 * lambda * press, wall), 0.0)
          << press << (wall ? " wall" : " pair");
      EXPECT_LT(luding_press_and_pull(press, 1.05 * lambda * press, wall), 0.0)
          << press << (wall ? " wall" : " pair");
    }
  }
}

}  // namespace
}  // namespace silodem
