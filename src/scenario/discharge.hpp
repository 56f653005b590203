// SPDX-License-Identifier: MIT
// Discharge: the valve opens at t = 0; a particle leaves when its centre crosses the outlet plane
// inside the outlet (that time is recorded, with its coal and mass) and is removed when it has
// fallen `sink_depth` below it. Particles found outside the walls, or crossing the outlet plane
// outside the outlet, are removed and counted as lost. Ends when the target fraction has left or
// the silo is empty, when nothing has left for `stall_time` (a stopped flow: arching, reported as
// such; the clock starts once a particle could have reached the sink), at `max_time`, or on a
// simulation error (the results up to then are kept).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "engine/simulation.hpp"
#include "scenario/case.hpp"

namespace silodem {

struct OutletRecord {
  double t = 0.0;  // s since the valve opened
  int coal = 0;
  double mass = 0.0;  // kg
};

struct DischargeState {
  double t = 0.0;  // s since the valve opened
  std::size_t particles_left = 0;
  double discharged = 0.0, lost = 0.0, filled = 0.0;
  double recent_rate = 0.0;  // kg/s over the last bin
};

enum class DischargeEnd { Emptied, FlowStopped, TimeLimit, Error };

struct DischargeResult {
  std::vector<OutletRecord> outflow;
  double filled_mass = 0.0, discharged_mass = 0.0, lost_mass = 0.0, remaining_mass = 0.0;
  long particles_filled = 0, particles_lost = 0;
  double discharge_time = 0.0;  // s from the valve opening to the last particle out
  double end_time = 0.0;        // s simulated after the valve opened
  DischargeEnd end = DischargeEnd::TimeLimit;
  std::string error;  // DischargeEnd::Error: what went wrong (results up to then kept)
  long steps = 0;
};

using DischargeProgress = std::function<void(const DischargeState&)>;

DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress);

// Mass of every particle in the simulation (kg).
double total_mass(const ParticleStore& p);

}  // namespace silodem
