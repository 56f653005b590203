// SPDX-License-Identifier: MIT
// What every normal law shares: the restitution of the original particles turned into the one the
// CG particles use, following the case's policy (Eq. 11; PHYSICS.md E4), with its warning.
#pragma once
#include "model/contact/registry.hpp"

namespace silodem {

// The `restitution` field of a normal law, coarse-grained; throws for an undefined value under
// the Energy policy, and collects the warning for `check`.
inline double normal_restitution(const ParamValues& v, const LawContext& ctx) {
  const RestitutionCg r = restitution_cg(v.number("restitution"), *ctx.cg);
  if (!r.defined && ctx.cg->restitution_policy == RestitutionPolicy::Energy)
    throw v.error("restitution", r.warning);
  if (!r.warning.empty() && ctx.warnings) ctx.warnings->push_back(r.warning);
  return r.value;
}

inline Field restitution_field() {
  return Field::number("restitution", "coefficient of restitution e of the original particles")
      .needed()
      .above(0)
      .at_most(1);
}

}  // namespace silodem
