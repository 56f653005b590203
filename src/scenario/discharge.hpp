// SPDX-License-Identifier: MIT
// Discharge: the valve opens at t = 0; particles that fall `sink_depth` below the outlet are
// removed and recorded (time, coal, mass); particles found outside the walls are removed and
// counted as lost. Ends when the target fraction has left, when nothing has left for
// `stall_time` (a stopped flow: arching, reported as such), or at `max_time`.
#pragma once
#include <functional>
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

enum class DischargeEnd { Emptied, FlowStopped, TimeLimit };

struct DischargeResult {
  std::vector<OutletRecord> outflow;
  double filled_mass = 0.0, discharged_mass = 0.0, lost_mass = 0.0, remaining_mass = 0.0;
  long particles_filled = 0, particles_lost = 0;
  double discharge_time = 0.0;  // s from the valve opening to the last particle out (or the end)
  double end_time = 0.0;        // s simulated after the valve opened
  DischargeEnd end = DischargeEnd::TimeLimit;
  long steps = 0;
};

using DischargeProgress = std::function<void(const DischargeState&)>;

DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress);

// Mass of every particle in the simulation (kg).
double total_mass(const ParticleStore& p);

}  // namespace silodem
