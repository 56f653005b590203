// SPDX-License-Identifier: MIT
// How the discharge classifies what leaves (issue 18, item 6): by where a centre crossed the
// outlet plane, not where the next check finds it; a particle outside the cone is lost, with a
// record of where it was; one that went out through the outlet and came back up outside the cone,
// round the rim, is discharged; the records survive a checkpoint. One sphere at a time in the
// paper's silo, gravity off (straight paths), so every number follows from the path by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "../../physics/helpers.hpp"
#include "scenario/discharge.hpp"

namespace silodem {
namespace {

constexpr double kR = 2e-3;          // sphere radius (m)
constexpr double kDt = 1e-3 / 64;    // 1e-3 / kDt is exactly 64: a check every 64 steps = 1 ms
constexpr double kCheck = 64 * kDt;  // = 1e-3 s

// The paper's silo (outlet radius 25 mm; cone from r = 25 mm at z = 0 to 234 mm at 633 mm),
// valve closed until Discharge::open(); spheres of radius 2 mm, 1500 kg/m^3.
struct Silo {
  SiloGeometry g;
  std::unique_ptr<Simulation> sim;
  std::size_t valve = 0;
  double m = test::sphere_mass_of(2 * kR, 1500);
  Silo() {
    SimulationSettings s;
    s.dt = kDt;
    s.threads = 1;
    sim = std::make_unique<Simulation>(test::model_of(test::Laws{}), s);
    sim->set_gravity({});
    SiloWalls w = make_silo_walls(g);
    valve = w.valve_index;
    for (auto& wall : w.walls) sim->add_wall(std::move(wall));
  }
  void add(const Vec3& x, const Vec3& v) { sim->particles().add(x, v, {}, kR, m, 0); }
};

DischargeSpec spec() {
  DischargeSpec s;
  s.bin = 0.01;
  s.sink_depth = 0.02;
  s.stall_time = 1.0;
  s.max_time = 0.1;
  return s;
}

TEST(DischargeClassification, DriftingSidewaysAfterTheOutletIsDischarged) {
  // From (14, 0, 1) mm at (15, 0, -10) m/s: the centre crosses z = 0 at t = 0.1 ms at
  // r = 14 + 1.5 = 15.5 mm, inside the 25 mm outlet; it passes the rim edge (25, 0) mm at
  // |(11, -1) x (15, -10)| / |(15, -10)| = 5.27 mm > its radius, touching nothing. At the first
  // check (1 ms) it is at r = 14 + 15 = 29 mm, z = -9 mm: beyond outlet radius + radius (27 mm),
  // where the check alone would have called it escaped past the rim. It reaches the sink
  // (z < -20 mm) at 2.1 ms and is removed at the check at 3 ms, recorded at its first check.
  Silo s;
  s.add({0.014, 0, 0.001}, {15, 0, -10});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::Emptied);
  EXPECT_EQ(r.particles_lost, 0);
  EXPECT_TRUE(r.lost.empty());
  ASSERT_EQ(r.outflow.size(), 1u);
  EXPECT_NEAR(r.outflow[0].t, kCheck, 1e-12);
  EXPECT_EQ(r.discharged_mass, s.m);
  EXPECT_NEAR(r.end_time, 3 * kCheck, 1e-12);
}

TEST(DischargeClassification, AtTheTimeLimitWhatIsFallingToTheSinkIsDischarged) {
  // From (0, 0, 1) mm at -0.1 m/s the centre crosses z = 0 at t = 10 ms (inside the outlet) and
  // would reach the sink (z < -20 mm) at 210 ms, after max_time (100 ms): at the time limit it is
  // between the outlet and the sink, has left the silo, and is booked at its crossing (the check
  // at 10 or 11 ms). A second sphere rests in the cone (gravity off) and stays.
  Silo s;
  s.add({0, 0, 0.001}, {0, 0, -0.1});
  s.add({0, 0, 0.3}, {});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::TimeLimit);
  ASSERT_EQ(r.outflow.size(), 1u);
  EXPECT_NEAR(r.outflow[0].t, 0.0105, 0.0006);
  EXPECT_EQ(r.discharged_mass, s.m);
  EXPECT_EQ(r.remaining_mass, s.m);
  EXPECT_EQ(s.sim->particles().size(), 1u);
  EXPECT_EQ(r.particles_lost, 0);
}

TEST(DischargeClassification, AtTheTimeLimitTheLastCheckBooksAtMaxTime) {
  // max_time 100.5 ms lies between two checks, so the last check is at 101 ms. From z = 502.5 mm
  // on the axis at -5 m/s the centre crosses z = 0 at 100.5 ms and is at -2.5 mm (wholly below the
  // plane) at 101 ms, the first check to see it below. It is booked at max_time, not at 101 ms,
  // so that the outlet bins end at max_time without a sliver bin after it.
  Silo s;
  s.add({0, 0, 0.5025}, {0, 0, -5.0});
  DischargeSpec sp = spec();
  sp.max_time = 0.1005;
  Discharge d(*s.sim, s.g, s.valve, sp);
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::TimeLimit);
  EXPECT_NEAR(r.end_time, 0.101, 1e-9);
  ASSERT_EQ(r.outflow.size(), 1u);
  EXPECT_EQ(r.outflow[0].t, 0.1005);
  EXPECT_EQ(r.discharged_mass, s.m);
}

TEST(DischargeClassification, AtTheEndWhatHangsAtTheOutletStaysAndWhatCrossedOutsideIsLost) {
  // At the time limit (100 ms), gravity off: a sphere at rest 1 mm below the outlet plane on the
  // axis (within a radius of the plane, not moving down: it may hang from the bed) stays in the
  // silo. A sphere from (40, 0, -1) mm at -0.1 m/s crossed z = 0 outside the 25 mm outlet (first
  // seen below it at r = 40 mm > 25 + 2 mm) and is at -11 mm, above the sink (-20 mm), at the end:
  // lost below the outlet, as the sink would have found it, not discharged.
  Silo s;
  s.add({0, 0, -0.001}, {});
  s.add({0.040, 0, -0.001}, {0, 0, -0.1});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::TimeLimit);
  EXPECT_TRUE(r.outflow.empty());
  EXPECT_EQ(r.discharged_mass, 0.0);
  ASSERT_EQ(r.lost.size(), 1u);
  EXPECT_EQ(r.lost[0].reason, LostReason::BelowOutsideOutlet);
  EXPECT_NEAR(r.lost[0].x.x, 0.040, 1e-12);
  EXPECT_NEAR(r.lost[0].x.z, -0.011, 2e-4);
  EXPECT_EQ(r.remaining_mass, s.m);
  EXPECT_EQ(s.sim->particles().size(), 1u);
  EXPECT_NEAR(r.filled_mass - (r.remaining_mass + r.discharged_mass + r.lost_mass), 0.0, 1e-18);
}

TEST(DischargeClassification, WhenEmptiedWhatIsFallingToTheSinkIsDischarged) {
  // target_fraction 0.5 of two spheres, gravity off. A from (0, 0, 1) mm at -1 m/s crosses at 1 ms
  // and reaches the sink (-20 mm) at 21 ms: removed at the check at 22 ms, which empties the silo
  // to the target. B from (10, 0, 1) mm at -0.2 m/s crossed inside the outlet at 5 ms and is at
  // -3.4 mm then, falling: it has left the silo and is booked at its crossing (the check at 5 or 6
  // ms), not left in the silo as undischarged.
  Silo s;
  s.add({0, 0, 0.001}, {0, 0, -1.0});
  s.add({0.010, 0, 0.001}, {0, 0, -0.2});
  DischargeSpec sp = spec();
  sp.target_fraction = 0.5;
  Discharge d(*s.sim, s.g, s.valve, sp);
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::Emptied);
  EXPECT_NEAR(r.end_time, 0.022, 1e-9);
  ASSERT_EQ(r.outflow.size(), 2u);
  EXPECT_NEAR(r.outflow[0].t, 0.0015, 0.0006);
  EXPECT_NEAR(r.outflow[1].t, 0.0055, 0.0006);
  EXPECT_EQ(r.discharged_mass, 2 * s.m);
  EXPECT_EQ(r.remaining_mass, 0.0);
}

TEST(DischargeClassification, OutsideTheConeIsLostWithItsRecord) {
  // Centre at z = 0.1 m, 4 mm (two radii) radially outside the cone, at rest: the cone face is
  // 4 cos(alpha) = 3.8 mm away behind it, beyond contact. The first check (1 ms) finds it outside
  // the wall (r > R(z) + radius) and records it: the cone nearest, at -4 mm cos(alpha), where
  // tan(alpha) = (234 - 25) / 633.
  Silo s;
  const double z = 0.1, x = s.g.radius_at(z) + 2 * kR;
  s.add({x, 0, z}, {});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::Emptied);
  EXPECT_TRUE(r.outflow.empty());
  EXPECT_EQ(r.particles_lost, 1);
  EXPECT_EQ(r.lost_mass, s.m);
  ASSERT_EQ(r.lost.size(), 1u);
  const LostRecord& l = r.lost[0];
  EXPECT_NEAR(l.t, kCheck, 1e-12);
  EXPECT_EQ(l.reason, LostReason::OutsideWall);
  EXPECT_STREQ(lost_reason_name(l.reason), "outside_wall");
  EXPECT_EQ(l.x.x, x);
  EXPECT_EQ(l.x.z, z);
  EXPECT_EQ(norm(l.v), 0.0);
  EXPECT_EQ(l.radius, kR);
  EXPECT_EQ(l.nearest.surface, SiloSurface::Cone);
  const double cos_alpha = 0.633 / std::hypot(0.633, 0.234 - 0.025);
  EXPECT_NEAR(l.nearest.distance, -2 * kR * cos_alpha, 1e-12);
  EXPECT_TRUE(std::isnan(l.crossing_r));  // it never crossed z = 0
}

TEST(DischargeClassification, OutThroughTheOutletAndRoundTheRimIsDischarged) {
  // What the default case's two "lost" particles did (docs/runs.md): out through the outlet, then
  // round the rim edge and up outside the cone. Here on a straight path: down the axis side at
  // r = 15 mm (crossing z = 0 at 0.4 ms, first check 1 ms), stopped at 3 ms (z = -13 mm), then
  // sent outwards and up at (5, 0, 3) m/s: it passes the rim edge at |(10, 13) x (5, 3)| / |(5, 3)|
  // = 6.0 mm and comes up through z = 0 at r = 15 + 13 * 5 / 3 = 36.7 mm, outside the cone.
  Silo s;
  s.add({0.015, 0, 0.002}, {0, 0, -5});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  DischargeControl stop_at_3ms;
  stop_at_3ms.stop = [&] { return s.sim->time() - d.t0() >= 3 * kCheck - 0.5 * kDt; };
  EXPECT_EQ(d.run({}, stop_at_3ms).end, DischargeEnd::Interrupted);
  EXPECT_NEAR(s.sim->particles().x[0].z, -0.013, 1e-12);
  s.sim->particles().v[0] = {5, 0, 3};
  const DischargeResult r = d.run({});
  EXPECT_EQ(r.end, DischargeEnd::Emptied);
  EXPECT_EQ(r.particles_lost, 0);
  EXPECT_EQ(r.particles_round_rim, 1);
  ASSERT_EQ(r.outflow.size(), 1u);
  EXPECT_NEAR(r.outflow[0].t, kCheck, 1e-12);
  // Up through z = 0 at 3 + 13 / 3 = 7.33 ms: removed at the check at 8 ms.
  EXPECT_NEAR(r.end_time, 8 * kCheck, 1e-12);
}

TEST(DischargeClassification, CrossingOutsideTheOutletIsLostAtTheSink) {
  // A centre going down through z = 0 at r = 35 mm, outside the 25 mm outlet: it came round
  // outside the cone (an escaped particle). It is lost when it reaches the sink: from z = -1 mm
  // at 5 m/s, z < -20 mm at 3.8 ms, the check at 4 ms (z = -21 mm).
  Silo s;
  s.add({0.035, 0, -0.001}, {0, 0, -5});
  Discharge d(*s.sim, s.g, s.valve, spec());
  d.open();
  const DischargeResult r = d.run({});
  EXPECT_TRUE(r.outflow.empty());
  ASSERT_EQ(r.lost.size(), 1u);
  const LostRecord& l = r.lost[0];
  EXPECT_EQ(l.reason, LostReason::BelowOutsideOutlet);
  EXPECT_NEAR(l.t, 4 * kCheck, 1e-12);
  EXPECT_NEAR(l.x.z, -0.021, 1e-12);
  EXPECT_EQ(l.crossing_r, 0.035);
  // Nearest: the rim circle, (10, -21) mm away, behind the plane (the cone face ends there too).
  EXPECT_NEAR(l.nearest.distance, -std::hypot(0.010, 0.021), 1e-12);
}

TEST(SiloGeometry, NearestSurfaceAndItsSide) {
  SiloGeometry g;
  g.valve_gap = 0.01;
  auto at = [&](Vec3 x, bool valve) { return g.nearest_surface(x, valve); };
  // 4 mm inside the cylinder wall (r = 234 mm), 0.8 m up.
  EXPECT_EQ(at({0.230, 0, 0.8}, false).surface, SiloSurface::Cylinder);
  EXPECT_NEAR(at({0, 0.230, 0.8}, false).distance, 0.004, 1e-12);
  // 3 mm behind it, above the cone/cylinder joint.
  EXPECT_NEAR(at({0.237, 0, 0.8}, false).distance, -0.003, 1e-12);
  // On the axis 3 mm above the opening (the rim is 25.2 mm away) and 8 mm below it.
  EXPECT_EQ(at({0, 0, 0.003}, false).surface, SiloSurface::OutletPlane);
  EXPECT_NEAR(at({0, 0, 0.003}, false).distance, 0.003, 1e-12);
  EXPECT_NEAR(at({0, 0, -0.008}, false).distance, -0.008, 1e-12);
  // With the valve closed, 10 mm below the outlet plane, the valve plate is 2 mm under that point.
  EXPECT_EQ(at({0, 0, -0.008}, true).surface, SiloSurface::Valve);
  EXPECT_NEAR(at({0, 0, -0.008}, true).distance, 0.002, 1e-12);
  // 10 mm above the cone face at mid-height, measured along its normal.
  const double th = g.half_angle(), z = 0.3;
  const Vec3 p{(g.radius_at(z) - 0.01 / std::cos(th)), 0, z};
  EXPECT_EQ(at(p, false).surface, SiloSurface::Cone);
  EXPECT_NEAR(at(p, false).distance, 0.01, 1e-12);
  EXPECT_STREQ(surface_name(SiloSurface::OutletPlane), "outlet_plane");
}

TEST(DischargeClassification, RecordsSurviveACheckpoint) {
  // A sphere lost at the first check (outside the cone), one still on its way through the
  // outlet (slowly: 0.5 m/s from z = 1 mm): interrupted at 2.5 ms, saved, loaded into a new
  // simulation and discharge, and run to the end, the result equals the uninterrupted run's.
  auto build = [](Silo& s) {
    s.add({s.g.radius_at(0.1) + 2 * kR, 0, 0.1}, {});
    s.add({0.01, 0, 0.001}, {0, 0, -0.5});
  };
  Silo a;
  build(a);
  Discharge da(*a.sim, a.g, a.valve, spec());
  da.open();
  const DischargeResult whole = da.run({});

  Silo b;
  build(b);
  Discharge db(*b.sim, b.g, b.valve, spec());
  db.open();
  DischargeControl stop;
  stop.stop = [&] { return b.sim->time() - db.t0() >= 2.5 * kCheck; };
  ASSERT_EQ(db.run({}, stop).end, DischargeEnd::Interrupted);
  ByteWriter w;
  b.sim->save(w);
  db.save(w);
  Silo c;
  Discharge dc(*c.sim, c.g, c.valve, spec());
  ByteReader rd(w.bytes());
  c.sim->load(rd);
  dc.load(rd);
  ASSERT_TRUE(rd.done());
  const DischargeResult resumed = dc.run({});

  ASSERT_EQ(whole.lost.size(), 1u);
  ASSERT_EQ(resumed.lost.size(), 1u);
  const LostRecord &x = whole.lost[0], &y = resumed.lost[0];
  EXPECT_EQ(x.t, y.t);
  EXPECT_EQ(x.id, y.id);
  EXPECT_EQ(x.x.x, y.x.x);
  EXPECT_EQ(x.reason, y.reason);
  EXPECT_EQ(x.nearest.surface, y.nearest.surface);
  EXPECT_EQ(x.nearest.distance, y.nearest.distance);
  EXPECT_TRUE(std::isnan(y.crossing_r));
  ASSERT_EQ(whole.outflow.size(), 1u);
  ASSERT_EQ(resumed.outflow.size(), 1u);
  EXPECT_EQ(whole.outflow[0].t, resumed.outflow[0].t);
  EXPECT_EQ(whole.end_time, resumed.end_time);
  EXPECT_EQ(resumed.particles_lost, 1);
}

}  // namespace
}  // namespace silodem
