// SPDX-License-Identifier: MIT
// Periodic boundaries (minimum image, wrapping, history across the boundary) and driven plates
// (set velocity, servo-held normal stress, the force they and the walls report).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>

#include "../../physics/helpers.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "engine/plate.hpp"
#include "engine/walls/plane.hpp"

namespace silodem {
namespace {

TEST(PeriodicBox, ImageAndWrap) {
  PeriodicBox b;
  b.set(0, -0.5, 2.0);
  EXPECT_NEAR(b.image({1.9, 0, 0}).x, -0.1, 1e-15);
  EXPECT_NEAR(b.image({-1.2, 0, 0}).x, 0.8, 1e-15);
  EXPECT_DOUBLE_EQ(b.image({0, 7.0, 0}).y, 7.0);  // y is not periodic
  EXPECT_NEAR(b.wrap({1.6, 0, 0}).x, -0.4, 1e-15);
  EXPECT_NEAR(b.wrap({-0.7, 0, 0}).x, 1.3, 1e-15);
  EXPECT_DOUBLE_EQ(b.wrap({-4.5, 0, 0}).x, -0.5);
  const double u = b.wrap({1.5 - 1e-17, 0, 0}).x;  // rounds onto the upper face: back to lo
  EXPECT_GE(u, -0.5);
  EXPECT_LT(u, 1.5);
}

// The list holds exactly the pairs within the cut-off through the nearest image, for boxes of
// many cells and of one or two cells along an axis (where the 27 neighbour cells alias).
TEST(VerletList, PeriodicMatchesMinimumImageBruteForce) {
  const double skin = 5e-4, reach = 0.05;
  // cut-off at most 2 x 3e-3 x 1.05 + 5e-4 = 6.8e-3 m: periods of 100, 15 and 14 mm
  for (const double len : {0.1, 0.015, 0.014}) {
    ParticleStore p;
    Random rng(11);
    PeriodicBox box;
    box.set(0, 0.0, len);
    box.set(1, -0.01, len);
    const int n = len > 0.05 ? 2000 : 60;
    for (int i = 0; i < n; ++i)
      p.add({rng.uniform(0, len), rng.uniform(-0.01, -0.01 + len), rng.uniform(0, 0.05)}, {}, {},
            rng.uniform(1e-3, 3e-3), 1e-4, 0);
    VerletList list;
    list.set_periodic(box);
    WallList none;
    list.build(p, none, skin, reach);
    std::set<std::pair<int, int>> got, want;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int e = list.offset[i]; e < list.offset[i + 1]; ++e)
        EXPECT_TRUE(got.insert({int(i), list.partner[e]}).second) << "pair listed twice";
    int across = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        const double cut = (p.radius[i] + p.radius[j]) * (1 + reach) + skin;
        if (norm2(box.image(p.x[i] - p.x[j])) < cut * cut) {
          want.insert({int(i), int(j)});
          across += norm2(p.x[i] - p.x[j]) < cut * cut ? 0 : 1;
        }
      }
    EXPECT_EQ(got, want) << "period " << len;
    EXPECT_GT(across, 10) << "the test must have pairs across the boundary";
  }
}

TEST(VerletList, RefusesAPeriodShorterThanTwoCutOffs) {
  ParticleStore p;
  p.add({0.001, 0, 0}, {}, {}, 1e-3, 1e-4, 0);
  PeriodicBox box;
  box.set(0, 0.0, 0.004);  // cut-off 2e-3 + 5e-4: needs 5 mm
  VerletList list;
  list.set_periodic(box);
  WallList none;
  try {
    list.build(p, none, 5e-4, 0.0);
    FAIL() << "no error";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("periodic box is 0.004 m long along x"), std::string::npos)
        << e.what();
  }
}

test::Laws frictional() {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.5}};
  return l;
}

SimulationSettings quiet(double dt = 1e-6) {
  SimulationSettings s;
  s.dt = dt;
  s.gravity = {};
  s.threads = 1;
  s.skin = 5e-4;
  return s;
}

// A collision across the x boundary is the collision in the middle of the box: the same
// relative motion (Galilean and translation invariance), to rounding.
TEST(Periodic, CollisionAcrossTheBoundaryIsTheCollisionInside) {
  auto run = [](bool across) {
    SimulationSettings s = quiet();
    s.periodic.set(0, 0.0, 0.02);
    Simulation sim(test::model_of(frictional()), s);
    auto& p = sim.particles();
    // a just left of the x = 0 face (x = 19.5 mm), b just right of it (x = 1 mm): 1.5 mm apart
    // through the boundary; inside: the same pair at x = 9.5 and 11 mm.
    const double xa = across ? 0.0195 : 0.0095, xb = across ? 0.001 : 0.011;
    p.add({xa, 0, 0}, {0.3, 0.05, 0}, {}, 1e-3, 1e-5, 0);
    p.add({xb, 0.0002, 0}, {-0.3, 0, 0}, {}, 1e-3, 1e-5, 0);
    sim.run_steps(40000);
    struct Out {
      Vec3 dx, dv, w;
      int crossings;
    } o{s.periodic.image(p.x[0] - p.x[1]), p.v[0] - p.v[1], p.omega[0], 0};
    return o;
  };
  const auto in = run(false), out = run(true);
  ASSERT_GT(norm(in.w), 1.0) << "friction must have acted";
  EXPECT_NEAR(out.dx.x, in.dx.x, 1e-12);
  EXPECT_NEAR(out.dx.y, in.dx.y, 1e-12);
  EXPECT_NEAR(out.dv.x, in.dv.x, 1e-9);
  EXPECT_NEAR(out.dv.y, in.dv.y, 1e-9);
  EXPECT_NEAR(out.w.z, in.w.z, 1e-6 * std::abs(in.w.z));
}

// A pair holding a static tangential load travels across the boundary at constant velocity: its
// spring stays what it is in the middle (the history is per pair, not per image), and the
// positions stay in the box.
TEST(Periodic, TangentialHistorySurvivesTheCrossing) {
  auto run = [](bool periodic) {
    SimulationSettings s = quiet();
    if (periodic) s.periodic.set(0, 0.0, 0.01);
    Simulation sim(test::model_of(frictional()), s);
    auto& p = sim.particles();
    const Vec3 v{2.0, 0, 0};  // 20 mm in 10 ms: two periods
    const auto a = p.add({0.004, 0, 0}, v, {}, 1e-3, 1e-5, 0);
    const auto b = p.add({0.004, 2e-3 - 1e-5, 0}, v, {}, 1e-3, 1e-5, 0);
    p.inv_mass[0] = 0.0, p.inv_inertia[0] = 0.0;  // a moves at v whatever the forces
    p.inv_inertia[1] = 0.0;                       // b cannot roll
    p.f_ext[1] = {0.02, -0.1, 0};                 // pressed onto a, sheared below mu F_n
    sim.run_steps(10000);
    bool flipped = false;
    const auto st = sim.contact_state(a, b, &flipped);
    struct Out {
      Vec3 spring, xb;
    } o{st ? (flipped ? -st->vec(0) : st->vec(0)) : Vec3{}, p.x[1]};
    return o;
  };
  const auto plain = run(false), pbc = run(true);
  ASSERT_GT(norm(plain.spring), 1e-7);
  EXPECT_NEAR(pbc.spring.x, plain.spring.x, 1e-6 * norm(plain.spring));
  EXPECT_NEAR(pbc.spring.y, plain.spring.y, 1e-6 * norm(plain.spring));
  EXPECT_GE(pbc.xb.x, 0.0);
  EXPECT_LT(pbc.xb.x, 0.01);
  EXPECT_GT(plain.xb.x, 0.02);  // the plain one really travelled two periods
}

// A sphere resting on a plane under gravity: the plane carries its weight (static equilibrium,
// the dashpot has died out).
TEST(WallForce, ASphereAtRestPressesThePlaneWithItsWeight) {
  SimulationSettings s = quiet(1e-5);
  s.gravity = {0, 0, -9.81};
  Simulation sim(test::model_of(frictional()), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{}, Vec3{0, 0, 1}));
  const double m = 1e-3;
  sim.particles().add({0, 0, 1e-3}, {}, {}, 1e-3, m, 0);
  sim.run_steps(200000);
  EXPECT_NEAR(sim.wall_force(0).z, -m * 9.81, 1e-6 * m * 9.81);
  EXPECT_NEAR(sim.wall_force(0).x, 0.0, 1e-12);
}

// A plate driven at a set velocity moves its wall and its glued particles by v t, together.
TEST(Plate, SetVelocityMovesWallAndGluedParticles) {
  Simulation sim(test::model_of(frictional()), quiet(1e-5));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0.01}, Vec3{0, 0, -1}));
  auto& p = sim.particles();
  p.add({0, 0, 0.009}, {}, {}, 1e-3, 1e-5, 0);
  p.add({0.003, 0, 0.009}, {}, {}, 1e-3, 1e-5, 0);
  Plate plate(sim, 0, {0, 1});
  plate.set_control({{0.1, 0, -0.05}});
  plate.add_to(sim);
  sim.run_steps(1000);  // 10 ms
  EXPECT_NEAR(plate.displacement().x, 1e-3, 1e-12);
  EXPECT_NEAR(plate.displacement().z, -5e-4, 1e-12);
  EXPECT_NEAR(p.x[0].x, 1e-3, 1e-12);
  EXPECT_NEAR(p.x[1].z, 0.009 - 5e-4, 1e-12);
  const auto* wall = dynamic_cast<const PlaneWall*>(&sim.wall(0));
  EXPECT_NEAR(wall->point().z, 0.01 - 5e-4, 1e-12);
  EXPECT_EQ(sim.wall(0).velocity().x, 0.1);
}

// A servo lid on a column of spheres between it and a fixed floor: at rest it holds the set
// stress (within the servo's tolerance, 0.5%), and the floor carries the same load (the column is
// in equilibrium: no gravity, so the two forces balance).
TEST(Plate, ServoHoldsTheNormalStressAndTheColumnIsInEquilibrium) {
  SimulationSettings s = quiet(2e-6);
  s.periodic.set(0, 0.0, 0.008);
  s.periodic.set(1, 0.0, 0.008);
  Simulation sim(test::model_of(frictional()), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0.0101}, Vec3{0, 0, -1}));
  auto& p = sim.particles();
  for (int iz = 0; iz < 5; ++iz)
    for (int iy = 0; iy < 4; ++iy)
      for (int ix = 0; ix < 4; ++ix)
        p.add({0.001 + 0.002 * ix, 0.001 + 0.002 * iy, 0.001 + 0.002 * iz}, {}, {}, 1e-3, 1e-5, 0);
  Plate lid(sim, 1, {});
  const double area = 0.008 * 0.008, stress = 500.0;  // 32 mN on 16 columns: 2 mN each
  // Gain: 16 lid contacts of k = 1e4 N/m and a dashpot of about 0.14 N s/m each: gain x (c + k
  // dt) = 0.05 x (2.2 + 0.3) < 1 (plate.hpp)
  lid.set_control({{}, true, stress, area, 0.05, 0.05});
  lid.add_to(sim);
  sim.run_steps(100000);
  const double target = stress * area;
  EXPECT_NEAR(lid.load(sim), target, 0.005 * target);
  EXPECT_NEAR(sim.wall_force(0).z, -target, 0.005 * target);
  // the lid came down 0.1 mm to the column and pressed it by F / k: 16 columns of 6 springs in
  // series, 2 mN x 6 / 1e4 N/m = 1.2 um
  EXPECT_NEAR(lid.displacement().z, -1e-4 - 1.2e-6, 0.02e-6);
}

// A sphere glued to a floor that sinks at v0 (a sample creeping at a steady speed) under a servo
// lid. The lid must follow at v0; a proportional servo does so only with the load off its target
// by v0 / gain (v = gain e, and the dashpot sees no relative speed then), the integral action
// takes that offset up.
double creeping_load(double integral_time, double* target_out) {
  SimulationSettings s = quiet(1e-6);
  Simulation sim(test::model_of(frictional()), s);
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 2.001e-3}, Vec3{0, 0, -1}));
  sim.particles().add({0, 0, 1e-3}, {}, {}, 1e-3, 1e-5, 0);
  Plate floor(sim, 0, {0});
  floor.set_control({{0, 0, -1e-3}});
  floor.add_to(sim);
  Plate lid(sim, 1);
  const double target = 0.01, gain = 1.0;  // gain (c + k dt) = 1 x (0.14 + 0.01) < 1
  lid.set_control({{}, true, target, 1.0, gain, 0.0, integral_time});
  lid.add_to(sim);
  sim.run_steps(50000);
  *target_out = target;
  return lid.load(sim);
}

TEST(Plate, IntegralActionTakesUpTheOffsetOfACreepingSample) {
  double target = 0;
  const double p_only = creeping_load(0.0, &target);
  EXPECT_NEAR(p_only, target - 1e-3 / 1.0, 0.01 * target);  // v0 / gain = 1e-3 N
  const double pi = creeping_load(1e-3, &target);
  EXPECT_NEAR(pi, target, 0.005 * target);
}

}  // namespace
}  // namespace silodem
