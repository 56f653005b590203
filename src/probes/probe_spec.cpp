// SPDX-License-Identifier: MIT
#include "probes/probe_spec.hpp"

#include "core/constants.hpp"

namespace silodem {

const std::vector<Bound<ProbeSpec>>& probe_fields() {
  using F = Field;
  using S = ProbeSpec;
  static const std::vector<Bound<S>> b = {
      bind(F::integer("every", "steps between samples; 0 = no probes").at_least(0).at_most(1e9),
           &S::every),
      bind(F::number_list("slab_times",
                          "times of the flow-pattern snapshots (default 0, 0.25, "
                          "0.5, 1, 2, 5, 10, 20, 40, 60, 80)",
                          "s")
               .at_least(0)
               .at_most(1e6),
           &S::slab_times),
      bind(F::number("slab_thickness_mm",
                     "thickness of the vertical slab through the axis (the "
                     "snapshots and the velocity profiles)",
                     "mm", units::mm)
               .above(0)
               .at_most(1e4),
           &S::slab_thickness),
      bind(F::number_list("profile_heights_mm",
                          "heights above the outlet of the velocity "
                          "profiles (default 100, 200, 300)",
                          "mm", units::mm)
               .at_least(0)
               .at_most(1e5),
           &S::profile_heights),
      bind(F::number("profile_bin_mm", "width of the profile bins (and their height)", "mm",
                     units::mm)
               .above(0)
               .at_most(1e4),
           &S::profile_bin),
      bind(F::number("profile_from", "start of the profiles' averaging window", "s")
               .at_least(0)
               .at_most(1e6),
           &S::profile_from),
      bind(F::number("profile_to", "end of the profiles' averaging window (default: the end)", "s")
               .above(0)
               .at_most(1e9),
           &S::profile_to),
      bind(F::number("adhesion_threshold",
                     "a particle is adhered when a partner's cohesive force "
                     "on it exceeds this",
                     "N")
               .at_least(0)
               .at_most(1e6),
           &S::adhesion_threshold),
      bind(F::number("level_radius_mm",
                     "particles within this distance of the axis define the "
                     "material level",
                     "mm", units::mm)
               .above(0)
               .at_most(1e4),
           &S::level_radius),
  };
  return b;
}

}  // namespace silodem
