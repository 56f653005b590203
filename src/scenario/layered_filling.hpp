// SPDX-License-Identifier: MIT
// Layered filling of the silo (PHYSICS.md 5, E7, E13): the fill height is split into equal
// segments, each gets the coal its scenario names; particles are inserted without overlap on a
// jittered lattice above the bed and settled under gravity with the valve closed and cohesion on.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "engine/simulation.hpp"
#include "scenario/case.hpp"

namespace silodem {

struct SegmentReport {
  int index = 0;  // 1 = H1 (bottom)
  int coal = 0;
  double z_low = 0, z_high = 0;                  // nominal segment bounds (m)
  double z_low_settled = 0, z_high_settled = 0;  // where its particles ended up (m)
  long particles = 0;
  double mass = 0.0, target_mass = 0.0;  // kg
  double bulk_density = 0.0;             // kg/m^3 of the settled layer (mass / volume it occupies)
  double bulk_density_measured = 0.0;    // the coal's measured value
  double solid_fraction = 0.0;           // bulk_density / true density
  double settle_time = 0.0;              // s of simulated settling after this segment's insertion
  bool settled = false;
};

struct FillReport {
  std::vector<SegmentReport> segments;
  long particles = 0;
  double mass = 0.0;
  double settle_time = 0.0;          // total simulated settling time (s)
  double max_boundary_offset = 0.0;  // |settled - nominal| over internal boundaries (m)
  std::vector<std::string> warnings;
};

using Progress = std::function<void(const std::string&)>;

// Fills `sim` (which already holds the silo walls with the valve closed). `segment_coal` gives
// the coal of each filled segment, bottom first.
FillReport fill_silo(Simulation& sim, const Case& c, const std::vector<int>& segment_coal,
                     Random& rng, const Progress& progress);

// Kinetic energy (translational + rotational) per particle (J).
double kinetic_energy_per_particle(const Simulation& sim);

}  // namespace silodem
