// SPDX-License-Identifier: MIT
// The lane evaluation of the pair loop (engine/pair_batch.hpp) against one contact at a time
// (evaluate_contact): for every law combination the vectorised lanes must give bitwise the same
// forces, torques, overlaps and history, so a run does not depend on how its pairs were batched.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "../../physics/helpers.hpp"
#include "engine/pair_batch.hpp"

namespace silodem {
namespace {

using test::Laws;

struct Pair {
  BodyState i, j;
  ContactState s;
};

BodyState body(std::mt19937_64& rng, const Vec3& x, double radius) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BodyState b;
  b.x = x;
  b.v = {u(rng), u(rng), u(rng)};
  // Some bodies at rest: the MFIX rolling law has a separate branch for zero spin.
  b.omega = u(rng) > 0.0 ? Vec3{20 * u(rng), 20 * u(rng), 20 * u(rng)} : Vec3{};
  b.radius = radius;
  b.mass = test::sphere_mass_of(2 * radius, 1400.0);
  b.inv_inertia = 1.0 / (0.4 * b.mass * radius * radius);
  b.inertia = 1.0 / b.inv_inertia;  // as the force loop computes it
  return b;
}

// Pairs from deep overlap to a gap beyond the longest cohesion range, with and without history,
// slipping and sticking.
std::vector<Pair> pairs(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), gap(-0.05, 0.08);
  std::vector<Pair> out;
  for (int k = 0; k < count; ++k) {
    const double ri = 0.004 * (1.0 + 0.5 * u(rng)), rj = 0.004 * (1.0 + 0.5 * u(rng));
    Vec3 dir{u(rng), u(rng), u(rng)};
    dir = dir / norm(dir);
    const double dist = (ri + rj) * (1.0 + gap(rng));
    Pair p{body(rng, {0.1, 0.2, 0.3}, ri), body(rng, Vec3{0.1, 0.2, 0.3} - dist * dir, rj), {}};
    if (k % 3 != 0)  // springs of 0.1 mm and torques of 1e-5 N m, as far as the laws keep any
      for (int m = 0; m < kMaxHistory; ++m) p.s.h[m] = (m < 3 ? 1e-4 : 1e-5) * u(rng);
    out.push_back(p);
  }
  return out;
}

void expect_same(const Vec3& a, const Vec3& b, const char* what, int k) {
  EXPECT_EQ(a.x, b.x) << what << " of pair " << k;
  EXPECT_EQ(a.y, b.y) << what << " of pair " << k;
  EXPECT_EQ(a.z, b.z) << what << " of pair " << k;
}

// All of `ps` through the lanes (full sets and a partial one), each against evaluate_contact.
void check_lanes_match(const ContactLaw& law, const std::vector<Pair>& ps) {
  const double dt = 2e-6;
  LaneSet set;
  int touching = 0;
  for (std::size_t start = 0; start < ps.size(); start += kLanes) {
    set.count = 0;
    const std::size_t end = std::min(ps.size(), start + kLanes);
    std::vector<ContactState> out(end - start);
    with_kernels(law, [&](auto kernels) {
      using K = decltype(kernels);
      constexpr int H = HistoryOf<K>::size;
      ASSERT_EQ(H, law.layout.size);
      for (std::size_t k = start; k < end; ++k) {
        const Pair& p = ps[k];
        set.add<H>(p.i.x - p.j.x, p.i.v, p.i.omega, p.i.radius, p.i.mass, p.i.inv_inertia, p.j.v,
                   p.j.omega, p.j.radius, p.j.mass, p.j.inv_inertia, p.s);
      }
      evaluate_lanes<K>(law, set, dt);
      for (std::size_t k = start; k < end; ++k) out[k - start] = set.state<H>(int(k - start));
    });
    for (std::size_t k = start; k < end; ++k) {
      const int l = int(k - start);
      ContactState s = ps[k].s;
      const ContactGeometry g = pair_geometry(ps[k].i, ps[k].j);
      const ContactResult r = evaluate_contact(law, g, s, dt);
      touching += r.touching ? 1 : 0;
      expect_same(LaneSet::get(set.f, l), r.force_i, "force on i", int(k));
      expect_same(LaneSet::get(set.ti, l), r.torque_i, "torque on i", int(k));
      expect_same(LaneSet::get(set.tj, l), r.torque_j, "torque on j", int(k));
      EXPECT_EQ(set.overlap[l], g.overlap) << "overlap of pair " << k;
      for (int m = 0; m < law.layout.size; ++m)
        EXPECT_EQ(out[std::size_t(l)].h[m], s.h[m]) << "history value " << m << " of pair " << k;
    }
  }
  // The sample has both kinds of pair, or the comparison proves little.
  EXPECT_GT(touching, 10);
  EXPECT_LT(touching, int(ps.size()) - 10);
}

Laws paper_laws() {  // the paper cases' combination
  Laws l;
  l.tangential = "linear_history";
  l.tangential_p = {{"friction", 0.3}};
  l.rolling = "mfix";
  l.rolling_p = {{"friction", 0.1}};
  l.cohesion = "overlap-only";
  return l;
}

TEST(PairBatch, LanesEqualOneContactAtATimeWithThePaperLaws) {
  const auto ps = pairs(3 * kLanes + 7, 1);
  check_lanes_match(test::law_of(paper_laws(), false, 0.02, 0.03), ps);
}

TEST(PairBatch, LanesEqualOneContactAtATimeWithEpsdAndRangedCohesion) {
  Laws l = paper_laws();
  l.rolling = "epsd";
  l.rolling_p = {{"friction", 0.2}};
  l.cohesion = "constant-range";
  l.cohesion_p = {{"range", 0.02}};
  check_lanes_match(test::law_of(l, false, 0.02, 0.02), pairs(2 * kLanes + 3, 2));
  l.cohesion = "mfix-like";
  l.cohesion_p = {{"inner", 0.001}, {"outer", 0.05}};
  check_lanes_match(test::law_of(l, false, 0.02, 0.01), pairs(2 * kLanes + 3, 3));
}

TEST(PairBatch, LanesEqualOneContactAtATimeWithoutFrictionOrCohesion) {
  check_lanes_match(test::law_of(Laws{}, false), pairs(2 * kLanes + 1, 4));
}

}  // namespace
}  // namespace silodem
