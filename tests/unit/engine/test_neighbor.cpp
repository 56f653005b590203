// SPDX-License-Identifier: MIT
// Neighbour list against brute force (polydisperse, size ratio 3), the rebuild criterion, and
// contact history across forced rebuilds and particle removal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

#include "../../physics/helpers.hpp"
#include "core/random.hpp"
#include "engine/walls/plane.hpp"

namespace silodem {
namespace {

TEST(VerletList, MatchesBruteForcePolydisperse) {
  ParticleStore p;
  Random rng(7);
  for (int i = 0; i < 2000; ++i) {
    const double r = rng.uniform(1e-3, 3e-3);  // size ratio 3
    p.add({rng.uniform(0, 0.1), rng.uniform(0, 0.1), rng.uniform(0, 0.05)}, {}, {}, r, 1e-4, 0);
  }
  const double skin = 5e-4, reach = 0.05;
  VerletList list;
  WallList none;
  list.build(p, none, skin, reach);
  std::set<std::pair<int, int>> got, want;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int e = list.offset[i]; e < list.offset[i + 1]; ++e) got.insert({int(i), list.partner[e]});
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double cut = (p.radius[i] + p.radius[j]) * (1 + reach) + skin;
      if (norm2(p.x[i] - p.x[j]) < cut * cut) want.insert({int(i), int(j)});
    }
  EXPECT_EQ(got, want);
  EXPECT_GT(want.size(), 1000u);
}

TEST(VerletList, RebuildOnlyAfterHalfSkin) {
  ParticleStore p;
  p.add({0, 0, 0}, {}, {}, 1e-3, 1e-4, 0);
  p.add({5e-3, 0, 0}, {}, {}, 1e-3, 1e-4, 0);
  VerletList list;
  WallList none;
  list.build(p, none, 1e-3, 0.0);
  p.x[0].x += 0.49e-3;
  EXPECT_FALSE(list.needs_rebuild(p));
  p.x[0].x += 0.02e-3;
  EXPECT_TRUE(list.needs_rebuild(p));
}

// Sphere b pressed onto a fixed sphere a and sheared by a force below the Coulomb limit, without
// rolling, so that the tangential spring holds a static load (skin 1 mm = the radius); not yet
// stepped. With `with_far`, a third sphere far away comes first in memory.
struct ShearedPair {
  std::unique_ptr<Simulation> sim;
  std::uint64_t a = 0, b = 0, far = 0;
  void load() {
    auto& q = sim->particles();
    q.f_ext[std::size_t(q.index_of(b))] = {-0.1, 0.02, 0};
  }
};
ShearedPair sheared_pair(bool with_far, bool reorder) {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.5}};
  SimulationSettings s;
  s.dt = 1e-6;
  s.gravity = {};
  s.threads = 1;
  s.skin = 1e-3;
  s.reorder_every = reorder ? 1 : 0;
  ShearedPair sp;
  sp.sim = std::make_unique<Simulation>(test::model_of(l), s);
  auto& p = sp.sim->particles();
  if (with_far) sp.far = p.add({1.0, 1.0, 1.0}, {}, {}, 1e-3, 1e-5, 0);
  sp.a = p.add({0, 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  sp.b = p.add({2e-3 - 1e-5, 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  p.inv_mass[std::size_t(p.index_of(sp.a))] = 0.0;  // a is fixed
  p.inv_inertia[std::size_t(p.index_of(sp.a))] = 0.0;
  p.inv_inertia[std::size_t(p.index_of(sp.b))] = 0.0;  // b cannot roll
  sp.load();
  return sp;
}
// The tangential spring of the pair and the positions after 1000 steps, optionally forcing a
// rebuild or removing the far sphere after 500.
struct Loaded {
  Vec3 spring, xa, xb;
};
Loaded loaded_pair(bool rebuild, bool remove_far, bool with_far, bool reorder = false) {
  ShearedPair sp = sheared_pair(with_far, reorder);
  Simulation& sim = *sp.sim;
  auto& p = sim.particles();
  const auto a = sp.a, b = sp.b;
  sim.run_steps(500);
  if (rebuild) sim.request_rebuild();
  if (remove_far) {
    sim.remove_particles({std::size_t(p.index_of(sp.far))});
    sp.load();
  }
  sim.run_steps(500);
  bool flipped = false;
  const std::optional<ContactState> st = sim.contact_state(a, b, &flipped);
  Loaded out;
  if (st) out.spring = flipped ? -st->vec(0) : st->vec(0);  // the tangential spring comes first
  out.xa = p.x[p.index_of(a)];
  out.xb = p.x[p.index_of(b)];
  return out;
}

TEST(ContactHistory, SurvivesForcedRebuild) {
  const Loaded plain = loaded_pair(false, false, false);
  const Loaded rebuilt = loaded_pair(true, false, false);
  EXPECT_GT(norm(plain.spring), 0.0);
  EXPECT_EQ(plain.spring.y, rebuilt.spring.y);
  EXPECT_EQ(plain.xa.y, rebuilt.xa.y);
  EXPECT_EQ(plain.xb.x, rebuilt.xb.x);
}

TEST(ContactHistory, SurvivesRemovalThatReordersParticles) {
  // Removing the far particle (index 0) moves a and b down by one (remove_all keeps the order;
  // ManyContactsSurviveRemovalReorderAndRebuildsByIndex below turns pairs around): the spring
  // must follow the renumbered pair.
  const Loaded alone = loaded_pair(false, false, false);
  const Loaded removed = loaded_pair(false, true, true);
  ASSERT_GT(norm(alone.spring), 0.0);
  EXPECT_NEAR(removed.spring.y / alone.spring.y, 1.0, 1e-9);
  EXPECT_NEAR(removed.xb.y / alone.xb.y, 1.0, 1e-9);
}

// Removing particles from a settling bed compacts the neighbour list instead of rebuilding it.
// A valid list holds every pair in range, in (i, j) order, whichever way it was made, so the
// forces, and with the Morton reorder off the whole trajectory, are bitwise those of the
// rebuild; only the number of builds differs.
TEST(VerletList, CompactionOnRemovalGivesTheTrajectoryOfARebuild) {
  auto run = [](bool rebuild_on_removal, int threads) {
    test::Laws l;
    l.normal_p = {{"stiffness", 1e3}, {"restitution", 0.3}};
    l.tangential = "linear_history";
    l.tangential_p = {{"friction", 0.5}};
    SimulationSettings s;
    s.dt = 1e-5;
    s.threads = threads;
    s.skin = 2e-4;
    s.reorder_every = 0;
    Simulation sim(test::model_of(l), s);
    sim.add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
    auto& p = sim.particles();
    Random rng(5);
    for (int i = 0; i < 1500; ++i)  // a loose lattice that falls onto the floor and piles up
      p.add({2.6e-3 * (i % 10) + rng.uniform(0, 2e-4), 2.6e-3 * (i / 10 % 10),
             1.5e-3 + 2.6e-3 * (i / 100) + rng.uniform(0, 2e-4)},
            {rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), 0}, {},
            rng.uniform(0.8e-3, 1.2e-3), 1e-5, 0);
    for (int round = 0; round < 8; ++round) {
      sim.run_steps(400);
      std::vector<std::size_t> out;
      for (std::size_t i = 0; i < p.size(); ++i)
        if ((p.id[i] + std::uint64_t(round)) % 37 == 0) out.push_back(i);
      if (rebuild_on_removal) sim.request_rebuild();
      sim.remove_particles(out);
    }
    sim.run_steps(400);
    return std::make_pair(p.x, sim.neighbors().builds);
  };
  for (int threads : {1, 2}) {
    const auto [x_rebuilt, builds_rebuilt] = run(true, threads);
    const auto [x_compacted, builds_compacted] = run(false, threads);
    ASSERT_EQ(x_rebuilt.size(), x_compacted.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < x_rebuilt.size(); ++i)
      differ += (x_rebuilt[i].x != x_compacted[i].x || x_rebuilt[i].y != x_compacted[i].y ||
                 x_rebuilt[i].z != x_compacted[i].z)
                    ? 1
                    : 0;
    EXPECT_EQ(differ, 0u) << threads << " threads";
    EXPECT_LT(builds_compacted, builds_rebuilt) << threads << " threads";
  }
}

// The per-particle skin (VerletList::skin_floor): each particle's allowance follows its speed,
// from floor x skin/2 at rest to skin/2 at half the top speed and above, and the list holds
// exactly the pairs within (r_i + r_j)(1 + reach) + a_i + a_j.
TEST(VerletList, SkinFloorGivesEachParticleItsOwnAllowance) {
  ParticleStore p;
  Random rng(11);
  for (int i = 0; i < 2000; ++i) {
    const double r = rng.uniform(1e-3, 3e-3);
    // A quarter of the particles move at up to 1 m/s, the others at up to 1 mm/s.
    const double v = i % 4 == 0 ? 1.0 : 1e-3;
    p.add({rng.uniform(0, 0.1), rng.uniform(0, 0.1), rng.uniform(0, 0.05)},
          {rng.uniform(-v, v), rng.uniform(-v, v), rng.uniform(-v, v)}, {}, r, 1e-4, 0);
  }
  const double skin = 5e-4, reach = 0.05, floor = 0.25;
  double v_max = 0.0;
  for (const Vec3& v : p.v) v_max = std::max(v_max, norm(v));
  VerletList fixed, own;
  WallList none;
  fixed.build(p, none, skin, reach);
  own.skin_floor = floor;
  own.build(p, none, skin, reach);
  std::set<std::pair<int, int>> got, want;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double a = 0.5 * skin * std::min(1.0, std::max(floor, 2.0 * norm(p.v[i]) / v_max));
    EXPECT_NEAR(own.allowance(i), a, 1e-15) << i;
    EXPECT_EQ(fixed.allowance(i), 0.5 * skin);
    for (int e = own.offset[i]; e < own.offset[i + 1]; ++e) got.insert({int(i), own.partner[e]});
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double cut =
          (p.radius[i] + p.radius[j]) * (1 + reach) + own.allowance(i) + own.allowance(j);
      if (norm2(p.x[i] - p.x[j]) < cut * cut) want.insert({int(i), int(j)});
    }
  }
  EXPECT_EQ(got, want);
  // The slow three quarters list fewer pairs than with the fixed skin.
  EXPECT_LT(double(own.partner.size()), 0.9 * double(fixed.partner.size()));
  // A slow particle's allowance is the floor's: it may move just under floor x skin/2.
  const std::size_t slow = 1;
  ASSERT_EQ(own.allowance(slow), floor * 0.5 * skin);
  p.x[slow].x += 0.99 * floor * 0.5 * skin;
  EXPECT_FALSE(own.needs_rebuild(p));
  EXPECT_FALSE(fixed.needs_rebuild(p));
  p.x[slow].x += 0.02 * floor * 0.5 * skin;
  EXPECT_TRUE(own.needs_rebuild(p));
  EXPECT_FALSE(fixed.needs_rebuild(p));

  // The allowances round-trip through the checkpoint; a damaged one (NaN would stop every
  // rebuild) is refused on load. The squared allowances are the last 8-byte values written.
  ByteWriter w;
  own.save(w);
  std::vector<unsigned char> bytes = w.bytes();
  VerletList back;
  ByteReader r(bytes);
  back.load(r);
  EXPECT_TRUE(r.done());
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_EQ(back.allowance(i), own.allowance(i)) << i;
  for (const double bad : {std::nan(""), -1e-12, 1.01 * 0.25 * skin * skin}) {
    std::memcpy(bytes.data() + bytes.size() - sizeof bad, &bad, sizeof bad);
    VerletList damaged;
    ByteReader rd(bytes);
    EXPECT_THROW(damaged.load(rd), std::runtime_error) << bad;
  }
}

// A pile falling onto a floor, particles removed now and then: with the Morton reorder off the
// per-particle skin changes which pairs out of range are listed and when the list is rebuilt,
// never a force, so the trajectory is bitwise that of the fixed skin. A checkpoint in the middle
// (with the allowances, tag LST3) resumes it bit for bit.
TEST(VerletList, SkinFloorGivesTheTrajectoryOfTheFixedSkin) {
  auto make = [](double floor, int threads) {
    test::Laws l;
    l.normal_p = {{"stiffness", 1e3}, {"restitution", 0.3}};
    l.tangential = "linear_history";
    l.tangential_p = {{"friction", 0.5}};
    SimulationSettings s;
    s.dt = 1e-5;
    s.threads = threads;
    s.skin = 4e-4;
    s.skin_floor = floor;
    s.reorder_every = 0;
    auto sim = std::make_unique<Simulation>(test::model_of(l), s);
    sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
    return sim;
  };
  auto fill = [](Simulation& sim) {
    auto& p = sim.particles();
    Random rng(5);
    for (int i = 0; i < 1500; ++i)
      p.add({2.6e-3 * (i % 10) + rng.uniform(0, 2e-4), 2.6e-3 * (i / 10 % 10),
             1.5e-3 + 2.6e-3 * (i / 100) + rng.uniform(0, 2e-4)},
            {rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), 0}, {},
            rng.uniform(0.8e-3, 1.2e-3), 1e-5, 0);
  };
  struct Result {
    std::vector<Vec3> x;
    long builds = 0;
    double listed = 0.0;  // listed pairs per particle, summed over the rounds
  };
  auto rounds = [](Simulation& sim, int from, int to, Result& out) {
    auto& p = sim.particles();
    for (int round = from; round < to; ++round) {
      sim.run_steps(400);
      out.listed += double(sim.neighbors().partner.size()) / double(p.size());
      std::vector<std::size_t> gone;
      for (std::size_t i = 0; i < p.size(); ++i)
        if ((p.id[i] + std::uint64_t(round)) % 37 == 0) gone.push_back(i);
      sim.remove_particles(gone);
    }
    out.x = p.x;
    out.builds = sim.neighbors().builds;
  };
  auto whole = [&](double floor, int threads) {
    auto sim = make(floor, threads);
    fill(*sim);
    Result r;
    rounds(*sim, 0, 10, r);
    return r;
  };
  for (int threads : {1, 2}) {
    const Result fixed = whole(1.0, threads), own = whole(0.25, threads);
    ASSERT_EQ(fixed.x.size(), own.x.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < fixed.x.size(); ++i)
      differ +=
          (fixed.x[i].x != own.x[i].x || fixed.x[i].y != own.x[i].y || fixed.x[i].z != own.x[i].z)
              ? 1
              : 0;
    EXPECT_EQ(differ, 0u) << threads << " threads";
    EXPECT_LT(own.listed, 0.97 * fixed.listed) << threads << " threads";
    EXPECT_NE(own.builds, fixed.builds) << threads << " threads: the rebuilds should move";

    // Interrupted after 5 rounds, saved, loaded into a new simulation, continued.
    auto first = make(0.25, threads);
    fill(*first);
    Result half;
    rounds(*first, 0, 5, half);
    ByteWriter w;
    first->save(w);
    const std::vector<unsigned char> bytes = w.bytes();
    const std::string tag3 = "LST3";
    EXPECT_NE(std::search(bytes.begin(), bytes.end(), tag3.begin(), tag3.end()), bytes.end());
    auto second = make(0.25, threads);
    ByteReader r(bytes);
    second->load(r);
    EXPECT_TRUE(r.done());
    Result resumed;
    rounds(*second, 5, 10, resumed);
    ASSERT_EQ(resumed.x.size(), own.x.size());
    differ = 0;
    for (std::size_t i = 0; i < own.x.size(); ++i)
      differ += (own.x[i].x != resumed.x[i].x || own.x[i].y != resumed.x[i].y ||
                 own.x[i].z != resumed.x[i].z)
                    ? 1
                    : 0;
    EXPECT_EQ(differ, 0u) << threads << " threads, resumed";
    EXPECT_EQ(resumed.builds, own.builds);
  }
}

TEST(ContactHistory, EndsWhenTheContactEnds) {
  // b is pressed onto the fixed a and sheared until the tangential spring holds a load; then it
  // is put 0.1 mm clear of a, inside the skin, so the pair stays listed and no rebuild runs. The
  // pair loop must forget the spring at the next step (a later touch starts from zero).
  ShearedPair sp = sheared_pair(false, false);
  Simulation& sim = *sp.sim;
  auto& p = sim.particles();
  sim.run_steps(500);
  bool flipped = false;
  const std::optional<ContactState> loaded = sim.contact_state(sp.a, sp.b, &flipped);
  ASSERT_TRUE(loaded);
  ASSERT_GT(norm(loaded->vec(0)), 0.0);
  const long builds = sim.neighbors().builds;
  const std::size_t ib = std::size_t(p.index_of(sp.b));
  p.x[ib] = {2e-3 + 1e-4, p.x[ib].y, 0};
  p.v[ib] = {};
  p.f_ext[ib] = {};
  sim.run_steps(3);
  EXPECT_EQ(sim.neighbors().builds, builds);  // the pair loop's doing, not a rebuild's
  const std::optional<ContactState> ended = sim.contact_state(sp.a, sp.b, &flipped);
  ASSERT_TRUE(ended);  // still listed
  EXPECT_EQ(norm(ended->vec(0)), 0.0);
}

TEST(ContactHistory, SurvivesMortonReorder) {
  // The far sphere comes first in memory; the Morton sort puts a and b (near the origin) first,
  // before the first build and again at the forced rebuild, while the spring is loaded.
  const Loaded plain = loaded_pair(true, false, true);
  const Loaded sorted = loaded_pair(true, false, true, true);
  ASSERT_GT(norm(plain.spring), 0.0);
  EXPECT_NEAR(sorted.spring.y / plain.spring.y, 1.0, 1e-12);
  EXPECT_NEAR(sorted.xb.y / plain.xb.y, 1.0, 1e-12);
}

TEST(Reorder, FreeFlightIsExactWhileParticlesAreSortedEveryBuild) {
  // Two spheres fly past each other (no contact, no gravity), with a skin so small that the list
  // is rebuilt, and the particles re-sorted, every few steps; their Morton order swaps midway.
  // Each must still move exactly with its own velocity: the sort happens in the middle of a step
  // and must carry everything the rest of the step reads per particle.
  test::Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  SimulationSettings s;
  s.dt = 1e-5;
  s.gravity = {};
  s.threads = 1;
  s.skin = 1e-4;
  s.reorder_every = 1;
  Simulation sim(test::model_of(l), s);
  auto& p = sim.particles();
  const auto a = p.add({0.3, 0, 0}, {-1.0, 0, 0}, {}, 1e-3, 1e-5, 0);
  const auto b = p.add({0.1, 0.05, 0}, {1.0, 0, 0.5}, {}, 1e-3, 1e-5, 0);
  const long steps = 20000;  // 0.2 s: they pass each other at 0.1 s
  sim.run_steps(1);
  EXPECT_EQ(p.index_of(b), 0);  // added second, sorted first: b is nearer the lowest corner
  sim.run_steps(steps - 1);
  const double t = double(steps) * s.dt;
  EXPECT_GT(sim.neighbors().builds, 100);
  EXPECT_EQ(p.index_of(a), 0);  // now a is
  EXPECT_NEAR(p.x[std::size_t(p.index_of(a))].x, 0.3 - t, 1e-12);
  EXPECT_NEAR(p.x[std::size_t(p.index_of(b))].x, 0.1 + t, 1e-12);
  EXPECT_NEAR(p.x[std::size_t(p.index_of(b))].z, 0.5 * t, 1e-12);
  EXPECT_EQ(p.v[std::size_t(p.index_of(a))].x, -1.0);
}

}  // namespace
}  // namespace silodem

namespace silodem {
// The history of many contacts through removals, a reordering and rebuilds at several thread
// counts, against a record kept by stable ids: every pair still listed keeps its own spring
// (turned when the pair's order in the list turns), every new pair starts from zero. The states
// are made from the ids, so a state attached to the wrong pair, or with the wrong sign, shows.
namespace {

// The history of a run with the tangential spring alone (3 values), or with a rolling spring
// and a scalar besides (7 values: the scalar, like a largest load, keeps its sign on a swap).
StateLayout layout_of(bool springs) {
  StateLayout l;
  l.size = springs ? 7 : 3;
  l.offset[1] = 0, l.count[1] = 3, l.law[1] = "linear_history";
  if (springs) {
    l.offset[2] = 3, l.count[2] = 3, l.law[2] = "epsd";
    l.offset[3] = 6, l.count[3] = 1, l.law[3] = "a-scalar";
  }
  for (int k = 0; k < l.size; ++k) l.swap[k] = k == 6 ? 1.0 : -1.0;
  return l;
}

ContactState state_of(std::uint64_t lo, std::uint64_t hi) {  // oriented "lo relative to hi"
  const double a = double(lo) + 1.0, b = double(hi) + 1.0;
  return {{a, -b, a * b, b, a, -a - b, a + 2 * b}};
}
// What the layout keeps of a state (the values beyond its size read as zero).
ContactState kept_of(const ContactState& s, const StateLayout& l) {
  ContactState o;
  for (int k = 0; k < l.size; ++k) o.h[k] = s.h[k];
  return o;
}

// Puts state_of(ids) on every listed pair (oriented by index order) and on every wall candidate.
void load_states(VerletList& list, const ParticleStore& p) {
  for (std::size_t i = 0; i + 1 < list.offset.size(); ++i) {
    for (int e = list.offset[i]; e < list.offset[i + 1]; ++e) {
      const std::uint64_t a = p.id[i], b = p.id[std::size_t(list.partner[e])];
      const ContactState s = state_of(std::min(a, b), std::max(a, b));
      list.set_state(std::size_t(e), a < b ? s : list.layout().swapped(s));
    }
    for (int e = list.wall_offset[i]; e < list.wall_offset[i + 1]; ++e)
      list.set_wall_state(std::size_t(e), state_of(p.id[i], 1000000 + std::uint64_t(list.wall[e])));
  }
}

bool same(const ContactState& a, const ContactState& b);

// Counts the listed pairs whose state is right: state_of(ids) for a pair listed before (in
// `before`, by ids), zero for a new one. Returns {right, kept from before}.
std::pair<std::size_t, std::size_t> check_states(
    const VerletList& list, const ParticleStore& p,
    const std::set<std::pair<std::uint64_t, std::uint64_t>>& before) {
  std::size_t right = 0, kept = 0;
  for (std::size_t i = 0; i + 1 < list.offset.size(); ++i)
    for (int e = list.offset[i]; e < list.offset[i + 1]; ++e) {
      const std::uint64_t a = p.id[i], b = p.id[std::size_t(list.partner[e])];
      const bool old = before.count({std::min(a, b), std::max(a, b)}) > 0;
      ContactState want{};
      if (old) {
        const ContactState s = state_of(std::min(a, b), std::max(a, b));
        want = kept_of(a < b ? s : list.layout().swapped(s), list.layout());
        ++kept;
      }
      right += same(list.state(std::size_t(e)), want) ? 1 : 0;
    }
  return {right, kept};
}

// The listed pairs by ids, and the wall candidates as (id, 1000000 + wall).
std::set<std::pair<std::uint64_t, std::uint64_t>> listed_ids(const VerletList& list,
                                                             const ParticleStore& p) {
  std::set<std::pair<std::uint64_t, std::uint64_t>> s;
  for (std::size_t i = 0; i + 1 < list.offset.size(); ++i) {
    for (int e = list.offset[i]; e < list.offset[i + 1]; ++e) {
      const std::uint64_t a = p.id[i], b = p.id[std::size_t(list.partner[e])];
      s.insert({std::min(a, b), std::max(a, b)});
    }
    for (int e = list.wall_offset[i]; e < list.wall_offset[i + 1]; ++e)
      s.insert({p.id[i], 1000000 + std::uint64_t(list.wall[e])});
  }
  return s;
}

bool same(const ContactState& a, const ContactState& b) {
  for (int k = 0; k < kMaxHistory; ++k)
    if (a.h[k] != b.h[k]) return false;
  return true;
}

// The wall candidates whose state is wrong (state_of(id, wall) if a candidate before, else 0).
std::size_t wrong_walls(const VerletList& list, const ParticleStore& p,
                        const std::set<std::pair<std::uint64_t, std::uint64_t>>& before) {
  std::size_t wrong = 0;
  for (std::size_t i = 0; i + 1 < list.offset.size(); ++i)
    for (int e = list.wall_offset[i]; e < list.wall_offset[i + 1]; ++e) {
      const std::uint64_t w = 1000000 + std::uint64_t(list.wall[e]);
      const ContactState want = before.count({p.id[i], w})
                                    ? kept_of(state_of(p.id[i], w), list.layout_walls())
                                    : ContactState{};
      wrong += same(list.wall_state(std::size_t(e)), want) ? 0 : 1;
    }
  return wrong;
}

}  // namespace

TEST(ContactHistory, ManyContactsSurviveRemovalReorderAndRebuildsByIndex) {
  for (int threads : {1, 2, 3, -1}) {  // -1: one thread, with the tangential spring alone
    ParticleStore p;
    Random rng(11);
    for (int i = 0; i < 3000; ++i)
      p.add({rng.uniform(0, 0.04), rng.uniform(0, 0.04), rng.uniform(0, 0.04)}, {}, {},
            rng.uniform(1e-3, 2e-3), 1e-5, 0);
    VerletList list;
    list.threads = std::max(threads, 1);
    list.set_layouts(layout_of(threads > 0), layout_of(threads > 0));
    WallList none;  // two walls that about a tenth of the particles touch
    none.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
    none.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{1, 0, 0}));
    list.build(p, none, 4e-4, 0.05);
    EXPECT_GT(list.wall.size(), 200u);
    EXPECT_EQ(list.hist.size(), list.partner.size() * (threads > 0 ? 7u : 3u));
    // 1. A rebuild after the particles moved a little: pairs come and go.
    load_states(list, p);
    auto before = listed_ids(list, p);
    for (auto& x : p.x) x += Vec3{rng.uniform(-3e-4, 3e-4), rng.uniform(-3e-4, 3e-4), 0.0};
    list.build(p, none, 4e-4, 0.05);
    auto [right, kept] = check_states(list, p, before);
    EXPECT_EQ(right, list.partner.size()) << threads << " threads, after moving";
    EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, after moving";
    EXPECT_GT(kept, list.partner.size() / 2);
    EXPECT_LT(kept, list.partner.size());  // some pairs are new
    // 2. Removing 200 particles, among them the last ones (whose slots the holes take).
    load_states(list, p);
    before = listed_ids(list, p);
    std::vector<std::size_t> gone;
    for (int k = 0; k < 200; ++k) gone.push_back(std::size_t(rng.uniform(0, 2999.99)));
    gone.push_back(p.size() - 1), gone.push_back(p.size() - 2), gone.push_back(5);
    list.stash_history(p);
    const std::vector<int> to = p.remove_all(gone);
    list.renumber(to);
    list.build(p, none, 4e-4, 0.05);
    std::tie(right, kept) = check_states(list, p, before);
    EXPECT_EQ(right, list.partner.size()) << threads << " threads, after removing";
    EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, after removing";
    EXPECT_GT(kept, list.partner.size() / 2);
    // 2a. The same removal done by compacting the list (Simulation::remove_particles's way):
    // with nothing moved since the build it is exactly the list a rebuild makes, with every
    // listed pair's own history, and x_at_build follows the particles.
    {
      load_states(list, p);
      before = listed_ids(list, p);
      std::vector<std::size_t> out;
      for (int k = 0; k < 150; ++k) out.push_back(std::size_t(rng.uniform(0, double(p.size()))));
      out.push_back(0), out.push_back(p.size() - 1);
      const std::vector<int> to2 = p.remove_all(out);
      ASSERT_TRUE(list.remove(p, to2));
      EXPECT_TRUE(list.built_for(p.size()));
      EXPECT_FALSE(list.needs_rebuild(p));
      VerletList fresh;
      fresh.threads = list.threads;
      fresh.set_layouts(list.layout(), list.layout_walls());
      fresh.build(p, none, 4e-4, 0.05);
      EXPECT_EQ(list.offset, fresh.offset) << threads << " threads, compacted";
      EXPECT_EQ(list.partner, fresh.partner) << threads << " threads, compacted";
      EXPECT_EQ(list.wall_offset, fresh.wall_offset) << threads << " threads, compacted";
      EXPECT_EQ(list.wall, fresh.wall) << threads << " threads, compacted";
      std::tie(right, kept) = check_states(list, p, before);
      EXPECT_EQ(right, list.partner.size()) << threads << " threads, compacted";
      EXPECT_EQ(kept, list.partner.size());
      EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, compacted";
      // A map that is not a removal in order, or for other particles, is refused untouched.
      std::vector<int> bad(p.size(), 0);
      EXPECT_FALSE(list.remove(p, bad));
      EXPECT_FALSE(list.remove(p, std::vector<int>(p.size() + 3, 0)));
      EXPECT_EQ(list.partner, fresh.partner);
    }
    // 2b. Two removals before one rebuild: the second stash call keeps the first stash, and the
    // two maps compose.
    load_states(list, p);
    before = listed_ids(list, p);
    list.stash_history(p);
    list.renumber(p.remove_all({0, 17, p.size() - 1}));
    list.stash_history(p);  // already stashed: returns at once
    list.renumber(p.remove_all({3, p.size() - 5}));
    list.build(p, none, 4e-4, 0.05);
    std::tie(right, kept) = check_states(list, p, before);
    EXPECT_EQ(right, list.partner.size()) << threads << " threads, after two removals";
    EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, after two removals";
    EXPECT_EQ(kept, list.partner.size());  // nothing moved: only pairs that were listed
    // 2c. Two particles trade places (the first and the last): the pairs of both turn, and the
    // stash is sorted again.
    load_states(list, p);
    before = listed_ids(list, p);
    {
      std::vector<std::size_t> order(p.size());
      std::vector<int> traded(p.size());
      for (std::size_t k = 0; k < p.size(); ++k) order[k] = k, traded[k] = int(k);
      std::swap(order.front(), order.back());
      std::swap(traded.front(), traded.back());
      list.stash_history(p);
      p.permute(order);
      list.renumber(traded);
    }
    list.build(p, none, 4e-4, 0.05);
    std::tie(right, kept) = check_states(list, p, before);
    EXPECT_EQ(right, list.partner.size()) << threads << " threads, after a swap";
    EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, after a swap";
    EXPECT_EQ(kept, list.partner.size());
    // 3. A full permutation (reversed order: every pair's orientation turns).
    load_states(list, p);
    before = listed_ids(list, p);
    std::vector<std::size_t> order(p.size());
    std::vector<int> to_rev(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
      order[k] = p.size() - 1 - k;
      to_rev[p.size() - 1 - k] = int(k);
    }
    list.stash_history(p);
    p.permute(order);
    list.renumber(to_rev);
    list.build(p, none, 4e-4, 0.05);
    std::tie(right, kept) = check_states(list, p, before);
    EXPECT_EQ(right, list.partner.size()) << threads << " threads, after reversing";
    EXPECT_EQ(wrong_walls(list, p, before), 0u) << threads << " threads, after reversing";
    EXPECT_EQ(kept, list.partner.size());  // nothing moved: the same pairs
  }
}

// A checkpoint names the law that kept each slot's history: a run with the same laws gets every
// value back, a run whose rolling law changed keeps the tangential springs and starts the
// rolling history from zero, and a run with a history the file does not have starts it at zero.
TEST(ContactHistory, CheckpointKeepsTheValuesOfTheLawsThatStayed) {
  ParticleStore p;
  for (int i = 0; i < 4; ++i) p.add({0.0019 * i, 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  WallList walls;
  walls.push_back(std::make_unique<PlaneWall>(Vec3{-1e-3, 0, 0}, Vec3{1, 0, 0}));
  VerletList list;
  list.set_layouts(layout_of(true), layout_of(true));
  list.build(p, walls, 5e-4, 0.0);
  ASSERT_EQ(list.partner.size(), 3u);
  ASSERT_EQ(list.wall.size(), 1u);
  load_states(list, p);
  ByteWriter w;
  list.save(w);
  auto load_as = [&](const StateLayout& l) {
    VerletList back;
    back.set_layouts(l, l);
    ByteReader r(w.bytes());
    back.load(r);
    EXPECT_TRUE(r.done());
    return back;
  };
  const VerletList same_laws = load_as(layout_of(true));
  EXPECT_EQ(same_laws.hist, list.hist);
  EXPECT_EQ(same_laws.wall_hist, list.wall_hist);
  StateLayout other = layout_of(true);
  other.law[int(Slot::Rolling)] = "another-rolling-law";
  const VerletList changed = load_as(other);
  for (std::size_t e = 0; e < 3; ++e) {
    const ContactState a = list.state(e), b = changed.state(e);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(b.h[k], a.h[k]) << "tangential " << k;
    for (int k = 3; k < 6; ++k) EXPECT_EQ(b.h[k], 0.0) << "rolling " << k;
    EXPECT_EQ(b.h[6], a.h[6]);  // the scalar's law stayed
  }
  const VerletList fewer = load_as(layout_of(false));
  ASSERT_EQ(fewer.hist.size(), 9u);
  for (std::size_t e = 0; e < 3; ++e)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(fewer.state(e).h[k], list.state(e).h[k]);
}

// Checkpoints from before the laws declared their history hold a tangential and a rolling spring
// per entry (tag LIST); they load into linear_history's and epsd's values.
TEST(ContactHistory, LoadsTheCheckpointsOfBefore) {
  struct Old {
    Vec3 tangential, rolling;
  };
  struct OldStash {
    std::uint64_t a, b;
    Old s;
  };
  const std::vector<int> offset{0, 1, 1}, partner{1}, wall_offset{0, 1, 1}, wall{0};
  ByteWriter w;
  w.tag("LIST");
  w.put(offset), w.put(partner), w.put(std::vector<Old>{{{1, 2, 3}, {4, 5, 6}}});
  w.put(wall_offset), w.put(wall), w.put(std::vector<Old>{{{7, 8, 9}, {10, 11, 12}}});
  w.put(long(5)), w.put(4e-4), w.put(std::vector<Vec3>{{0, 0, 0}, {1e-3, 0, 0}});
  w.put(std::uint8_t(0)), w.put(std::vector<OldStash>{}), w.put(std::vector<OldStash>{});
  VerletList list;
  list.set_layouts(layout_of(true), layout_of(false));
  ByteReader r(w.bytes());
  list.load(r);
  EXPECT_TRUE(r.done());
  EXPECT_EQ(list.builds, 5);
  const ContactState s = list.state(0), ws = list.wall_state(0);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(s.h[k], k + 1.0);
  EXPECT_EQ(s.h[6], 0.0);  // a value the old files never had
  for (int k = 0; k < 3; ++k) EXPECT_EQ(ws.h[k], k + 7.0);
  EXPECT_EQ(list.wall_hist.size(), 3u);  // the walls keep the tangential spring alone
}

TEST(ParticleStore, RemoveAllSaysWhereEachParticleWent) {
  ParticleStore p;
  for (int i = 0; i < 10; ++i) p.add({double(i), 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  const std::vector<int> to = p.remove_all({9, 2, 2, 0, 7});
  ASSERT_EQ(p.size(), 6u);
  ASSERT_EQ(to.size(), 10u);
  for (std::uint64_t id = 0; id < 10; ++id) {
    const bool removed = id == 0 || id == 2 || id == 7 || id == 9;
    EXPECT_EQ(to[id], removed ? -1 : int(p.index_of(id))) << "id " << id;
  }
  // The others keep their order (and their data).
  const std::vector<std::uint64_t> left = {1, 3, 4, 5, 6, 8};
  EXPECT_EQ(p.id, left);
  for (std::size_t k = 0; k < p.size(); ++k) EXPECT_EQ(p.x[k].x, double(p.id[k]));
  EXPECT_THROW(p.remove_all({6}), std::out_of_range);
}

TEST(VerletList, RefusesParticlesReorderedBehindItsBack) {
  // The history goes by index: particles moved without stash_history + renumber would attach it
  // to the wrong pairs, so the next rebuild stops with a logic error instead.
  ParticleStore p;
  for (int i = 0; i < 4; ++i) p.add({2e-3 * i, 0, 0}, {}, {}, 1.1e-3, 1e-5, 0);
  VerletList list;
  WallList none;
  list.build(p, none, 1e-4, 0.0);
  p.permute({1, 0, 2, 3});
  EXPECT_THROW(list.build(p, none, 1e-4, 0.0), std::logic_error);
  // Appending particles is fine: the old indices still hold.
  ParticleStore q;
  for (int i = 0; i < 4; ++i) q.add({2e-3 * i, 0, 0}, {}, {}, 1.1e-3, 1e-5, 0);
  VerletList l2;
  l2.build(q, none, 1e-4, 0.0);
  q.add({8e-3, 0, 0}, {}, {}, 1.1e-3, 1e-5, 0);
  EXPECT_NO_THROW(l2.build(q, none, 1e-4, 0.0));
  EXPECT_EQ(l2.partner.size(), 4u);
}

namespace {

TEST(VerletList, StrayParticlesAreFoundAndDoNotBreakTheGrid) {
  // 3000 packed spheres plus two strays far away, close to each other: the strays must not blow
  // up the grid (cells stay one cutoff wide) and their pair must still be found.
  ParticleStore p;
  Random rng(5);
  for (int i = 0; i < 3000; ++i)
    p.add({rng.uniform(0, 0.05), rng.uniform(0, 0.05), rng.uniform(0, 0.05)}, {}, {}, 1e-3, 1e-5,
          0);
  p.add({40.0, -30.0, 100.0}, {}, {}, 1e-3, 1e-5, 0);
  p.add({40.0015, -30.0, 100.0}, {}, {}, 1e-3, 1e-5, 0);
  VerletList list;
  WallList none;
  list.build(p, none, 2e-4, 0.0);
  std::size_t pairs = 0, brute = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    pairs += std::size_t(list.offset[i + 1] - list.offset[i]);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      brute += norm2(p.x[i] - p.x[j]) < 2.2e-3 * 2.2e-3 ? 1 : 0;
  EXPECT_EQ(pairs, brute);
  const std::size_t a = p.size() - 2;
  ASSERT_EQ(list.offset[a + 1] - list.offset[a], 1);
  EXPECT_EQ(list.partner[std::size_t(list.offset[a])], int(a + 1));
}

}  // namespace
}  // namespace silodem
