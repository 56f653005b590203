// SPDX-License-Identifier: MIT
// Neighbour list against brute force (polydisperse, size ratio 3), the rebuild criterion, and
// contact history across forced rebuilds and particle removal.
#include <gtest/gtest.h>

#include <set>

#include "../../physics/helpers.hpp"
#include "core/random.hpp"

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
// rolling, so that the tangential spring holds a static load; a third sphere far away. Returns the
// tangential spring of the pair and the positions after `steps`, optionally forcing rebuilds or
// removing the far sphere mid-way.
struct Loaded {
  Vec3 spring, xa, xb;
};
Loaded loaded_pair(bool rebuild, bool remove_far, bool with_far, bool reorder = false) {
  test::Laws l;
  l.normal_p = {{"stiffness", 1e4}, {"restitution", 0.5}};
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.5}};
  SimulationSettings s;
  s.dt = 1e-6;
  s.gravity = {};
  s.threads = 1;
  s.reorder_every = reorder ? 1 : 0;
  Simulation sim(test::model_of(l), s);
  auto& p = sim.particles();
  std::uint64_t far = 0;
  if (with_far) far = p.add({1.0, 1.0, 1.0}, {}, {}, 1e-3, 1e-5, 0);
  const auto a = p.add({0, 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  const auto b = p.add({2e-3 - 1e-5, 0, 0}, {}, {}, 1e-3, 1e-5, 0);
  p.inv_mass[p.index_of(a)] = 0.0;  // a is fixed
  p.inv_inertia[p.index_of(a)] = 0.0;
  p.inv_inertia[p.index_of(b)] = 0.0;  // b cannot roll
  auto set_loads = [&]() {
    auto& q = sim.particles();
    q.f_ext[q.index_of(b)] = {-0.1, 0.02, 0};
  };
  set_loads();
  sim.run_steps(500);
  if (rebuild) sim.request_rebuild();
  if (remove_far) {
    sim.remove_particles({std::size_t(p.index_of(far))});
    set_loads();
  }
  sim.run_steps(500);
  bool flipped = false;
  const ContactState* st = sim.contact_state(a, b, &flipped);
  Loaded out;
  if (st) out.spring = flipped ? -st->tangential : st->tangential;
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
  // Removing the far particle (index 0) swaps b into slot 0: the pair is now stored as (b, a), and
  // its spring must be carried over with the sign flipped.
  const Loaded alone = loaded_pair(false, false, false);
  const Loaded removed = loaded_pair(false, true, true);
  ASSERT_GT(norm(alone.spring), 0.0);
  EXPECT_NEAR(removed.spring.y / alone.spring.y, 1.0, 1e-9);
  EXPECT_NEAR(removed.xb.y / alone.xb.y, 1.0, 1e-9);
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
