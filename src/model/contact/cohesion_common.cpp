// SPDX-License-Identifier: MIT
#include "model/contact/cohesion_common.hpp"

#include <algorithm>

namespace silodem {

std::vector<Field> cohesion_common_fields(bool wall) {
  Field factor =
      Field::number("factor",
                    "multiplies F_L,cg (Eq. 13-14): a calibration of the moisture force; "
                    "1 = the paper's")
          .with_default(1.0)
          .at_least(0)
          .at_most(100);
  if (wall)
    return {Field::number("wall_factor",
                          "wall cohesive force as a multiple of the particle's own F_L,cg")
                .with_default(1.0)
                .at_least(0)
                .at_most(100),
            factor};
  return {Field::text("pair_rule", "F_L,cg between two different coals",
                      {"mean", "min", "harmonic"}, "mean"),
          factor};
}

double cohesion_pair_rule(const std::string& rule, double f_a, double f_b) {
  if (rule == "min") return std::min(f_a, f_b);
  if (rule == "harmonic") return f_a + f_b > 0.0 ? 2.0 * f_a * f_b / (f_a + f_b) : 0.0;
  return 0.5 * (f_a + f_b);
}

double cohesion_pair_force(const ParamValues& v, const LawContext& ctx) {
  const double f = v.number("factor");
  if (ctx.wall) return f * v.number("wall_factor") * ctx.cohesion_i;
  return f * cohesion_pair_rule(v.string("pair_rule"), ctx.cohesion_i, ctx.cohesion_j);
}

}  // namespace silodem
