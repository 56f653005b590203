// SPDX-License-Identifier: MIT
#include "scenario/discharge.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

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
  // Checks about every 1 ms of simulated time: a particle near the outlet moves by less than its
  // own size in that time.
  const long check_every = std::max(1L, long(1e-3 / sim.dt()));
  const double fall = std::sqrt(2.0 * spec.sink_depth / 9.81);  // outlet plane to sink
  double last_out = 0.0, bin_mass = 0.0, bin_start = 0.0;
  std::unordered_map<std::uint64_t, double> crossed;  // id -> time its centre crossed z = 0
  DischargeState st;
  st.filled = r.filled_mass;
  std::vector<std::size_t> remove;
  try {
    for (;;) {
      sim.run_steps(check_every);
      const double t = sim.time() - t0;
      remove.clear();
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double z = p.x[i].z;
        const double r_xy = std::hypot(p.x[i].x, p.x[i].y);
        if (z < 0.0 && !crossed.count(p.id[i])) {
          // Left through the outlet, or past the rim outside it (escaped: lost).
          crossed[p.id[i]] = r_xy <= g.outlet_radius() + p.radius[i] ? t : -1.0;
        }
        bool lost = (z >= 0.0 && r_xy > g.radius_at(z) + p.radius[i]) || z > g.total_height() + 0.5;
        if (z < -spec.sink_depth) {
          const double t_out = crossed.count(p.id[i]) ? crossed[p.id[i]] : t;
          if (t_out < 0.0) {
            lost = true;
          } else {
            r.outflow.push_back({t_out, p.material[i], p.mass[i]});
            r.discharged_mass += p.mass[i];
            bin_mass += p.mass[i];
            last_out = t;
            remove.push_back(i);
            continue;
          }
        }
        if (lost) {
          r.lost_mass += p.mass[i];
          ++r.particles_lost;
          remove.push_back(i);
        }
      }
      for (std::size_t i : remove) crossed.erase(p.id[i]);
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
      if (r.discharged_mass >= spec.target_fraction * r.filled_mass || p.size() == 0) {
        r.end = DischargeEnd::Emptied;
        break;
      }
      if (t - std::max(last_out, fall) >= spec.stall_time) {
        r.end = DischargeEnd::FlowStopped;
        break;
      }
      if (t >= spec.max_time) {
        r.end = DischargeEnd::TimeLimit;
        break;
      }
    }
  } catch (const SimulationError& e) {
    r.end = DischargeEnd::Error;
    r.error = e.what();
  }
  // Outflow times are crossing times, which are not monotone in the order of removal.
  std::stable_sort(r.outflow.begin(), r.outflow.end(),
                   [](const OutletRecord& a, const OutletRecord& b) { return a.t < b.t; });
  r.end_time = sim.time() - t0;
  r.discharge_time = r.outflow.empty() ? 0.0 : r.outflow.back().t;
  r.remaining_mass = total_mass(p);
  r.steps = sim.step_count() - steps0;
  return r;
}

}  // namespace silodem
