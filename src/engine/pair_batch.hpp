// SPDX-License-Identifier: MIT
// Particle-particle contacts evaluated several at a time (docs/architecture.md, "The pair loop in
// lanes"). The force loop (simulation.cpp) walks the neighbour list as before, but instead of
// evaluating each pair in range at once it copies the two bodies and the history into lane arrays
// (structure of arrays): one LaneSet per contact law, i.e. per coal pair. Every kLanes pairs it
// evaluates each set in one loop that the compiler vectorises, calling the same evaluate<K> as a
// single contact (every law is still written once, in its own file), then adds the results to the
// force buffers in list order. The arithmetic of each lane and the order of the sums are those of
// the one-contact loop, so the forces are bitwise the same (tests/unit/engine/test_pair_batch.cpp).
//
// What keeps the lane loop vectorisable: the law's numbers come from one plain LawParamsOf<K> per
// set, copied out of the ContactLaw before the loop (uniform across the lanes: no gathers, no
// flags read per lane), the lanes are contiguous arrays,
// and every kernel is branch-light enough for if-conversion. A law that breaks this still runs,
// only one lane at a time: check with -fopt-info-vec (bench/README.md).
#pragma once
#include <vector>

#include "core/inline.hpp"
#include "model/contact/contact_model.hpp"
#include "model/contact/dispatch.hpp"

// Three versions of the lane loop in the portable build, chosen when the program starts:
// x86-64-v4 where the CPU has AVX-512 (4 doubles per instruction as AVX2, but 32 vector registers
// instead of 16, so the loop keeps more of its values in registers and spills fewer of them to
// the stack; the gain: BENCHMARKS.md, "What the engine does to be fast"), AVX2, and
// the x86-64 baseline (SSE2, 2 doubles) elsewhere. CMakeLists.txt turns off fused multiply-adds
// and 512-bit vectors for the portable build, so all three give the rounding of the scalar code.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define SILODEM_LANE_CLONES [[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]]
#else
#define SILODEM_LANE_CLONES
#endif
// "The lanes are independent", in GCC's spelling. Clang knows no `GCC ivdep` (with -Werror the
// unknown pragma is an error) and does not vectorise this loop when asked (it warns instead), so
// a clang build (the fuzzer's) runs it one lane at a time.
#if defined(__GNUC__) && !defined(__clang__)
#define SILODEM_LANES_INDEPENDENT _Pragma("GCC ivdep")
#else
#define SILODEM_LANES_INDEPENDENT
#endif

namespace silodem {

inline constexpr int kLanes = 64;

// Up to kLanes contacts of one law: inputs, the history (read and written back) and outputs.
struct LaneSet {
  int count = 0;
  // d = x_i - x_j (all the geometry needs of the positions: pair_geometry with x_i = d and
  // x_j = 0 computes d - 0 = d, bitwise), then the velocities and spins.
  alignas(64) double d[3][kLanes], vi[3][kLanes], vj[3][kLanes];
  alignas(64) double wi[3][kLanes], wj[3][kLanes];
  alignas(64) double ri[kLanes], rj[kLanes], mi[kLanes], mj[kLanes], inv_ii[kLanes], inv_ij[kLanes];
  alignas(64) double hist[kMaxHistory][kLanes];  // the laws' history values (contact_history.hpp)
  alignas(64) double f[3][kLanes], ti[3][kLanes], tj[3][kLanes], overlap[kLanes];

  // Copies one pair in (x_i - x_j, i's data, j's data, the H history values); returns its lane.
  template <int H>
  SILODEM_HOT int add(const Vec3& x_ij, const Vec3& v_i, const Vec3& w_i, double r_i, double m_i,
                      double inv_i_i, const Vec3& v_j, const Vec3& w_j, double r_j, double m_j,
                      double inv_i_j, const ContactState& s) {
    const int l = count++;
    put(d, l, x_ij), put(vi, l, v_i), put(wi, l, w_i);
    put(vj, l, v_j), put(wj, l, w_j);
    ri[l] = r_i, mi[l] = m_i, inv_ii[l] = inv_i_i;
    rj[l] = r_j, mj[l] = m_j, inv_ij[l] = inv_i_j;
    for (int k = 0; k < H; ++k) hist[k][l] = s.h[k];
    return l;
  }
  static Vec3 get(const double (&a)[3][kLanes], int l) { return {a[0][l], a[1][l], a[2][l]}; }
  template <int H>
  ContactState state(int l) const {
    ContactState s;
    for (int k = 0; k < H; ++k) s.h[k] = hist[k][l];
    return s;
  }

 private:
  static void put(double (&a)[3][kLanes], int l, const Vec3& v) {
    a[0][l] = v.x, a[1][l] = v.y, a[2][l] = v.z;
  }
};

// Evaluates the `count` contacts of one set with the laws K and the numbers `law` (PHYSICS.md
// 2-3 through evaluate<K>): forces on i, torques on i and j, overlaps, and the new history.
template <class K>
SILODEM_LANE_CLONES void evaluate_lanes(const ContactLaw& law, LaneSet& b, double dt) {
  constexpr int H = HistoryOf<K>::size;
  const LawParamsOf<K> lp = typed_params<K>(law);  // once, before the loop: nothing per lane
  const int count = b.count;
  SILODEM_LANES_INDEPENDENT
  for (int l = 0; l < count; ++l) {
    const BodyState bi{{b.d[0][l], b.d[1][l], b.d[2][l]},
                       {b.vi[0][l], b.vi[1][l], b.vi[2][l]},
                       {b.wi[0][l], b.wi[1][l], b.wi[2][l]},
                       b.ri[l],
                       b.mi[l],
                       1.0 / b.inv_ii[l],
                       b.inv_ii[l]};
    const BodyState bj{{0.0, 0.0, 0.0},
                       {b.vj[0][l], b.vj[1][l], b.vj[2][l]},
                       {b.wj[0][l], b.wj[1][l], b.wj[2][l]},
                       b.rj[l],
                       b.mj[l],
                       1.0 / b.inv_ij[l],
                       b.inv_ij[l]};
    const ContactGeometry g = pair_geometry(bi, bj);
    ContactState s;
    for (int k = 0; k < H; ++k) s.h[k] = b.hist[k][l];
    const ContactResult r = evaluate<K>(lp, g, s, dt);
    b.f[0][l] = r.force_i.x, b.f[1][l] = r.force_i.y, b.f[2][l] = r.force_i.z;
    b.ti[0][l] = r.torque_i.x, b.ti[1][l] = r.torque_i.y, b.ti[2][l] = r.torque_i.z;
    b.tj[0][l] = r.torque_j.x, b.tj[1][l] = r.torque_j.y, b.tj[2][l] = r.torque_j.z;
    b.overlap[l] = g.overlap;
    for (int k = 0; k < H; ++k) b.hist[k][l] = s.h[k];
  }
}

// One thread's pairs in flight: up to kLanes of them in list order, each in the set of its law.
struct alignas(64) PairWindow {
  struct Entry {
    int i, j, e;    // particles and list entry
    int set, lane;  // where its data are
  };
  std::vector<LaneSet> sets;            // one per law (material pair a * n + b)
  std::vector<const ContactLaw*> laws;  // each set's law
  std::vector<int> hits, misses;        // one particle's list entries in range and out of range
  double reach = 1.0;                   // 1 + the longest reach_over_d of the sets' laws
  Entry entries[kLanes];
  int count = 0;
  char pad[64];  // the next thread's window starts on another cache line

  bool full() const { return count == kLanes; }
};

}  // namespace silodem
