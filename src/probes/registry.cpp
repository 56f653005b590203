// SPDX-License-Identifier: MIT
#include "probes/registry.hpp"

#include "probes/probes.hpp"

namespace silodem {

const std::vector<ProbeEntry>& probe_registry() {
  static const std::vector<ProbeEntry> table = {
      {"slab", "particles in a vertical slab through the axis at chosen times (flow pattern)",
       make_slab_probe},
      {"velocity_profile", "time-averaged vertical velocity across the width at chosen heights",
       make_velocity_profile_probe},
      {"adhesion", "share of particles held by a cohesive force above a threshold",
       make_adhesion_probe},
      {"cohesion_force", "mean and largest cohesive force on the particles in the hopper",
       make_cohesion_force_probe},
      {"level", "material level on the centre line", make_level_probe},
      {"coordination", "mean number of touching particle partners", make_coordination_probe},
  };
  return table;
}

std::vector<std::unique_ptr<Probe>> make_probes(const ProbeSpec& spec, const ProbeSite& site) {
  std::vector<std::unique_ptr<Probe>> out;
  if (spec.every <= 0) return out;
  for (const auto& e : probe_registry()) out.push_back(e.make(spec, site));
  return out;
}

}  // namespace silodem
