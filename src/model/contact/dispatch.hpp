// SPDX-License-Identifier: MIT
// Compile-time dispatch over the laws of laws.hpp. `with_kernels(law, f)` calls f with a
// Kernels<Normal, Tangential, Rolling, Cohesion> value naming the four laws `law` was configured
// with, so a force loop written as a template over Kernels is compiled once per combination with
// every kernel inlined: no call through a pointer, and the geometry a law does not read is never
// computed. `evaluate<K>` is the one composition of the four slots (PHYSICS.md 2-3).
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/inline.hpp"
#include "model/contact/contact_history.hpp"
#include "model/contact/contact_model.hpp"
#include "model/contact/laws.hpp"

namespace silodem {

template <class N, class T, class R, class C>
struct Kernels {
  using Normal = N;
  using Tangential = T;
  using Rolling = R;
  using Cohesion = C;
};

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) pick_law(int index, F&& f) {
  if constexpr (sizeof...(Rest) == 0) {
    return f(First{});
  } else {
    if (index == 0) return f(First{});
    return pick_law<F, Rest...>(index - 1, std::forward<F>(f));
  }
}
template <class... Laws, class F>
decltype(auto) pick(LawList<Laws...>, int index, F&& f) {
  return pick_law<F, Laws...>(index, std::forward<F>(f));
}
}  // namespace detail

template <class F>
decltype(auto) with_kernels(const ContactLaw& law, F&& f) {
  const int* ix = law.law_index;
  return detail::pick(NormalLaws{}, ix[0], [&](auto n) -> decltype(auto) {
    return detail::pick(TangentialLaws{}, ix[1], [&](auto t) -> decltype(auto) {
      return detail::pick(RollingLaws{}, ix[2], [&](auto r) -> decltype(auto) {
        return detail::pick(CohesionLaws{}, ix[3], [&](auto c) -> decltype(auto) {
          return f(Kernels<decltype(n), decltype(t), decltype(r), decltype(c)>{});
        });
      });
    });
  });
}

// The numbers of the four laws of K, each law's own Params: what the force loop reads, copied
// out of a ContactLaw once (typed_params) so that nothing in the loop looks into a variant.
template <class K>
struct LawParamsOf {
  typename K::Normal::Params n;
  typename K::Tangential::Params t;
  typename K::Rolling::Params r;
  typename K::Cohesion::Params c;
};
template <class K>
LawParamsOf<K> typed_params(const ContactLaw& law) {
  return {law.params<typename K::Normal>(), law.params<typename K::Tangential>(),
          law.params<typename K::Rolling>(), law.params<typename K::Cohesion>()};
}

// Where each slot's history values sit in a contact's state (slot order, as StateLayout).
template <class K>
struct HistoryOf {
  static constexpr int normal = 0;
  static constexpr int tangential = normal + history_size<typename K::Normal>;
  static constexpr int rolling = tangential + history_size<typename K::Tangential>;
  static constexpr int cohesion = rolling + history_size<typename K::Rolling>;
  static constexpr int size = cohesion + history_size<typename K::Cohesion>;
  static_assert(size <= kMaxHistory, "the four laws keep more history than kMaxHistory");
};

// One contact: all four slots, combined as PHYSICS.md 2-3 say. Clears the history when the
// surfaces do not touch (history lives as long as the contact).
template <class K>
SILODEM_HOT ContactResult evaluate(const LawParamsOf<K>& p, const ContactGeometry& g,
                                   ContactState& s, double dt) {
  using H = HistoryOf<K>;
  ContactResult r;
  if (g.overlap <= 0.0) {
    // Not touching: only a ranged cohesion acts; the contact (and its history) has ended.
    r.cohesion = K::Cohesion::kernel(p.c, g, NormalForce{}, s.h + H::cohesion);
    for (int k = 0; k < H::size; ++k) s.h[k] = 0.0;
    r.force_i = -r.cohesion * g.n;
    return r;
  }
  r.touching = true;
  const NormalForce fn = K::Normal::kernel(p.n, g, s.h + H::normal);
  r.cohesion = K::Cohesion::kernel(p.c, g, fn, s.h + H::cohesion);
  r.normal = fn.total;
  const Vec3 ft = K::Tangential::kernel(p.t, g, fn, r.cohesion, s.h + H::tangential, dt);
  // Torque of the tangential force about each centre: r x F with r = -arm_i n (on i) and
  // r = +arm_j n with force -F_t (on j); both equal -arm (n x F_t).
  const Vec3 nxf = cross(g.n, ft);
  const RollingTorque rt = K::Rolling::kernel(p.r, g, fn, r.cohesion, s.h + H::rolling, dt);
  r.torque_i = -g.arm_i * nxf + rt.on_i;
  r.torque_j = -g.arm_j * nxf + rt.on_j;
  r.force_i = (fn.total - r.cohesion) * g.n + ft;
  return r;
}

}  // namespace silodem
