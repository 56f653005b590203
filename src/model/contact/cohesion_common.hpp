// SPDX-License-Identifier: MIT
// What every moisture-cohesion range law shares: the force F_L,cg of a pair (PHYSICS.md 3, E9):
// between two coals a pair rule (mean / min / harmonic of their F_L,cg), against a wall a factor
// on the particle's own F_L,cg.
#pragma once
#include <vector>

#include "model/contact/registry.hpp"

namespace silodem {

std::vector<Field> cohesion_common_fields(bool wall);
double cohesion_pair_force(const ParamValues& v, const LawContext& ctx);
// mean | min | harmonic of two forces.
double cohesion_pair_rule(const std::string& rule, double f_a, double f_b);

}  // namespace silodem
