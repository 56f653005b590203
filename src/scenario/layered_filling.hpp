// SPDX-License-Identifier: MIT
// Layered filling of the silo (PHYSICS.md 5, E7, E13): the fill height is split into equal
// segments, each gets the coal its scenario names; particles are inserted without overlap on a
// jittered lattice above the bed and settled under gravity with the valve closed and cohesion on.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/bytes.hpp"
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

  void save(ByteWriter& w) const;
  void load(ByteReader& r);
};

using Progress = std::function<void(const std::string&)>;

// Where a fill stands between two settling chunks: with the Simulation's own checkpoint, enough to
// continue it bit for bit after a kill (run_silo writes both into checkpoint.bin).
struct FillProgress {
  std::size_t segment = 0;  // the segment being filled (0 = H1)
  int phase = 0;            // 0: not inserted yet; 1: settling; 2: cut at its top, settling again
  SegmentReport seg;        // the segment being filled, so far
  double start = 0.0;       // top of the bed before this segment (m)
  double settle_t0 = 0.0;   // simulated time when the current settling began (s)
  double min_time = 0.0;    // the current settling's shortest duration (s)
  int below = 0;            // consecutive checks below the kinetic-energy threshold
  FillReport report;        // the segments done, and the warnings so far
  std::vector<std::uint64_t> first_id;  // first particle id of each segment begun
  std::uint64_t rng = 0;                // the random generator's state

  void save(ByteWriter& w) const;
  void load(ByteReader& r);
};

// Called between settling chunks (every 2 ms of simulated time) with the fill's progress; the
// caller decides whether to checkpoint it, and may throw to stop the fill.
using FillCheckpoint = std::function<void(const FillProgress&)>;

// Fills `sim` (which already holds the silo walls with the valve closed). `segment_coal` gives
// the coal of each filled segment, bottom first. With `from`, continues an interrupted fill (sim
// loaded from the same checkpoint).
FillReport fill_silo(Simulation& sim, const ScenarioCase& c, const std::vector<int>& segment_coal,
                     Random& rng, const Progress& progress, const FillCheckpoint& checkpoint = {},
                     const FillProgress* from = nullptr);

// Kinetic energy (translational + rotational) per particle (J).
double kinetic_energy_per_particle(const Simulation& sim);

}  // namespace silodem
