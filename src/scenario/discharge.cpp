// SPDX-License-Identifier: MIT
#include "scenario/discharge.hpp"

#include <cmath>

namespace silodem {

double total_mass(const ParticleStore& p) {
  double m = 0.0;
  for (double x : p.mass) m += x;
  return m;
}

DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress) {
  DischargeResult r;
  auto& p = sim.particles();
  r.filled_mass = total_mass(p);
  r.particles_filled = long(p.size());
  sim.set_wall_enabled(valve_index, false);  // t = 0: the valve opens
  const double t0 = sim.time();
  const long steps0 = sim.step_count();
  // Sink check about every 1 ms of simulated time: a particle at the sink moves by less than
  // its own size in that time. Escape check every 10 ms.
  const long sink_every = std::max(1L, long(1e-3 / sim.dt()));
  const long escape_every = 10 * sink_every;
  double last_out = 0.0, bin_mass = 0.0, bin_start = 0.0;
  DischargeState st;
  st.filled = r.filled_mass;
  std::vector<std::size_t> remove;
  for (;;) {
    sim.run_steps(sink_every);
    const double t = sim.time() - t0;
    remove.clear();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.x[i].z < -spec.sink_depth) {
        r.outflow.push_back({t, p.material[i], p.mass[i]});
        r.discharged_mass += p.mass[i];
        bin_mass += p.mass[i];
        last_out = t;
        remove.push_back(i);
      }
    if ((sim.step_count() - steps0) % escape_every < sink_every) {
      // Lost: outside the wall by more than a radius, or above the silo.
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double z = p.x[i].z;
        if (z < -spec.sink_depth) continue;
        const bool in_throat = z < 0.0;
        const double r_xy = std::hypot(p.x[i].x, p.x[i].y);
        const bool outside = (!in_throat && r_xy > g.radius_at(z) + p.radius[i]) ||
                             z > g.total_height() + 0.5;
        if (outside) {
          r.lost_mass += p.mass[i];
          ++r.particles_lost;
          remove.push_back(i);
        }
      }
    }
    sim.remove_particles(remove);
    if (t - bin_start >= spec.bin) {
      st.recent_rate = bin_mass / (t - bin_start);
      bin_mass = 0.0;
      bin_start = t;
    } else if (t < spec.bin) {
      st.recent_rate = r.discharged_mass / t;  // first bin: the running mean
    }
    st.t = t;
    st.particles_left = p.size();
    st.discharged = r.discharged_mass;
    st.lost = r.lost_mass;
    if (progress) progress(st);
    if (r.discharged_mass >= spec.target_fraction * r.filled_mass) {
      r.end = DischargeEnd::Emptied;
      break;
    }
    if (t - last_out >= spec.stall_time) {
      r.end = DischargeEnd::FlowStopped;
      break;
    }
    if (t >= spec.max_time) {
      r.end = DischargeEnd::TimeLimit;
      break;
    }
  }
  r.end_time = sim.time() - t0;
  r.discharge_time = r.end == DischargeEnd::Emptied ? last_out : r.end_time;
  r.remaining_mass = total_mass(p);
  r.steps = sim.step_count() - steps0;
  return r;
}

}  // namespace silodem
