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

// One contact: all four slots, combined as PHYSICS.md 2-3 say. Clears the history when the
// surfaces do not touch (history lives as long as the contact). Law: anything with the four
// parameter blocks np, tp, rp, cp (a ContactLaw, or the plain LawParams of the lane loop).
template <class K, class Law>
SILODEM_HOT ContactResult evaluate(const Law& law, const ContactGeometry& g, ContactState& s,
                                   double dt) {
  ContactResult r;
  r.cohesion = K::Cohesion::kernel(law.cp, g);
  if (g.overlap <= 0.0) {
    // Not touching: only a ranged cohesion acts; the contact (and its history) has ended.
    s = ContactState{};
    r.force_i = -r.cohesion * g.n;
    return r;
  }
  r.touching = true;
  const NormalForce fn = K::Normal::kernel(law.np, g);
  r.normal = fn.total;
  const double cap =
      law.tp.cap_sees_cohesion ? std::max(0.0, fn.total - r.cohesion) : std::fabs(fn.total);
  const Vec3 ft = K::Tangential::kernel(law.tp, g, fn.eta, cap, s.tangential, dt);
  // Torque of the tangential force about each centre: r x F with r = -arm_i n (on i) and
  // r = +arm_j n with force -F_t (on j); both equal -arm (n x F_t).
  const Vec3 nxf = cross(g.n, ft);
  const RollingTorque rt = K::Rolling::kernel(law.rp, g, law.np, fn, r.cohesion, s.rolling, dt);
  r.torque_i = -g.arm_i * nxf + rt.on_i;
  r.torque_j = -g.arm_j * nxf + rt.on_j;
  r.force_i = (fn.total - r.cohesion) * g.n + ft;
  return r;
}

}  // namespace silodem
