// SPDX-License-Identifier: MIT
// What the probes are told by a case: their [probes] section (ProbeSpec) and the extent of the
// silo they watch (ProbeSite). The probes see nothing else of the case or of the scenario layer.
#pragma once
#include <vector>

#include "core/schema.hpp"

namespace silodem {

// Probes of a silo run, sampled every `every` steps of the discharge.
struct ProbeSpec {
  long every = 1000;  // steps; 0 = no probes
  std::vector<double> slab_times{0.0, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 60.0, 80.0};
  double slab_thickness = 0.02;                        // m
  std::vector<double> profile_heights{0.1, 0.2, 0.3};  // m above the outlet
  double profile_bin = 0.01;                           // m
  double profile_from = 0.0, profile_to = 1e9;         // s, averaging window
  double adhesion_threshold = 1e-3;                    // N
  double level_radius = 0.02;                          // m around the axis
};

// The silo the probes watch (axis at x = y = 0, outlet plane at z = 0).
struct ProbeSite {
  double silo_radius = 0.0;  // m, the widest radius (the cylinder's)
};

// The [probes] keys, bound to ProbeSpec's members (probes/probe_spec.cpp).
const std::vector<Bound<ProbeSpec>>& probe_fields();

}  // namespace silodem
