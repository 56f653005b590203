// SPDX-License-Identifier: MIT
#include "scenario/discharge.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace silodem {

double total_mass(const ParticleStore& p) {
  double m = 0.0;
  for (double x : p.mass) m += x;
  return m;
}

Discharge::Discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                     const DischargeSpec& spec)
    : sim_(sim), g_(g), valve_(valve_index), spec_(spec) {
  // Checks about every 1 ms of simulated time: a particle near the outlet moves by less than its
  // own size in that time.
  check_every_ = std::max(1L, long(1e-3 / sim.dt()));
  fall_ = std::sqrt(2.0 * spec.sink_depth / 9.81);  // outlet plane to sink
}

void Discharge::open() {
  auto& p = sim_.particles();
  r_.filled_mass = total_mass(p);
  r_.particles_filled = long(p.size());
  sim_.set_wall_enabled(valve_, false);  // t = 0: the valve opens
  t0_ = sim_.time();
  steps0_ = sim_.step_count();
}

void Discharge::check(double t, std::vector<std::size_t>& remove) {
  auto& p = sim_.particles();
  remove.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z = p.x[i].z;
    const double r_xy = std::hypot(p.x[i].x, p.x[i].y);
    if (z < 0.0 && !crossed_.count(p.id[i])) {
      // Left through the outlet, or past the rim outside it (escaped: lost).
      crossed_[p.id[i]] = r_xy <= g_.outlet_radius() + p.radius[i] ? t : -1.0;
    }
    bool lost = (z >= 0.0 && r_xy > g_.radius_at(z) + p.radius[i]) || z > g_.total_height() + 0.5;
    if (z < -spec_.sink_depth) {
      const auto it = crossed_.find(p.id[i]);
      const double t_out = it != crossed_.end() ? it->second : t;
      if (t_out < 0.0) {
        lost = true;
      } else {
        r_.outflow.push_back({t_out, p.material[i], p.mass[i]});
        r_.discharged_mass += p.mass[i];
        bin_mass_ += p.mass[i];
        last_out_ = t;
        remove.push_back(i);
        continue;
      }
    }
    if (lost) {
      r_.lost_mass += p.mass[i];
      ++r_.particles_lost;
      remove.push_back(i);
    }
  }
  for (std::size_t i : remove) crossed_.erase(p.id[i]);
  sim_.remove_particles(remove);
}

DischargeResult Discharge::run(const DischargeProgress& progress, const DischargeControl& control) {
  auto& p = sim_.particles();
  DischargeState st;
  st.filled = r_.filled_mass;
  std::vector<std::size_t> remove;
  using Clock = std::chrono::steady_clock;
  auto last_checkpoint = Clock::now();
  try {
    for (;;) {
      while (step_in_interval_ < check_every_) {
        sim_.step();
        ++step_in_interval_;
        if (control.stop && control.stop()) {
          DischargeResult out = finish(r_);
          out.end = DischargeEnd::Interrupted;
          return out;
        }
      }
      step_in_interval_ = 0;
      const double t = sim_.time() - t0_;
      check(t, remove);
      if (t - bin_start_ >= spec_.bin) {
        recent_rate_ = bin_mass_ / (t - bin_start_);
        bin_mass_ = 0.0;
        bin_start_ = t;
      } else if (t < spec_.bin) {
        recent_rate_ = r_.discharged_mass / t;  // first bin: the running mean
      }
      st.t = t;
      st.recent_rate = recent_rate_;
      st.particles_left = p.size();
      st.discharged = r_.discharged_mass;
      st.lost = r_.lost_mass;
      if (progress) progress(st);
      if (r_.discharged_mass >= spec_.target_fraction * r_.filled_mass || p.size() == 0) {
        r_.end = DischargeEnd::Emptied;
        break;
      }
      if (t - std::max(last_out_, fall_) >= spec_.stall_time) {
        r_.end = DischargeEnd::FlowStopped;
        break;
      }
      if (t >= spec_.max_time) {
        r_.end = DischargeEnd::TimeLimit;
        break;
      }
      const bool by_time = control.checkpoint_interval > 0 && t >= next_checkpoint_;
      const bool by_wall = control.checkpoint_wall_interval > 0 &&
                           std::chrono::duration<double>(Clock::now() - last_checkpoint).count() >=
                               control.checkpoint_wall_interval;
      if (by_time) next_checkpoint_ = t + control.checkpoint_interval;
      if ((by_time || by_wall) && control.checkpoint) {
        control.checkpoint();
        last_checkpoint = Clock::now();
      }
    }
  } catch (const SimulationError& e) {
    r_.end = DischargeEnd::Error;
    r_.error = e.what();
  }
  return finish(r_);
}

DischargeResult Discharge::finish(DischargeResult r) const {
  // Outflow times are crossing times, which are not monotone in the order of removal.
  std::stable_sort(r.outflow.begin(), r.outflow.end(),
                   [](const OutletRecord& a, const OutletRecord& b) { return a.t < b.t; });
  r.end_time = sim_.time() - t0_;
  r.discharge_time = r.outflow.empty() ? 0.0 : r.outflow.back().t;
  r.remaining_mass = total_mass(sim_.particles());
  r.steps = sim_.step_count() - steps0_;
  return r;
}

void Discharge::save(ByteWriter& w) const {
  w.tag("DISC");
  w.put(t0_), w.put(steps0_), w.put(step_in_interval_), w.put(next_checkpoint_);
  w.put(last_out_), w.put(bin_mass_), w.put(bin_start_), w.put(recent_rate_);
  std::vector<std::uint64_t> ids;
  std::vector<double> times;
  for (const auto& [id, t] : crossed_) ids.push_back(id), times.push_back(t);
  w.put(ids), w.put(times);
  std::vector<double> out_t, out_m;
  std::vector<int> out_c;
  for (const auto& o : r_.outflow)
    out_t.push_back(o.t), out_c.push_back(o.coal), out_m.push_back(o.mass);
  w.put(out_t), w.put(out_c), w.put(out_m);
  w.put(r_.filled_mass), w.put(r_.discharged_mass), w.put(r_.lost_mass);
  w.put(r_.particles_filled), w.put(r_.particles_lost);
}

void Discharge::load(ByteReader& rd) {
  rd.tag("DISC");
  rd.get(t0_), rd.get(steps0_), rd.get(step_in_interval_), rd.get(next_checkpoint_);
  rd.get(last_out_), rd.get(bin_mass_), rd.get(bin_start_), rd.get(recent_rate_);
  std::vector<std::uint64_t> ids;
  std::vector<double> times;
  rd.get(ids), rd.get(times);
  if (ids.size() != times.size()) throw std::runtime_error("checkpoint: discharge records differ");
  crossed_.clear();
  for (std::size_t k = 0; k < ids.size(); ++k) crossed_[ids[k]] = times[k];
  std::vector<double> out_t, out_m;
  std::vector<int> out_c;
  rd.get(out_t), rd.get(out_c), rd.get(out_m);
  if (out_c.size() != out_t.size() || out_m.size() != out_t.size())
    throw std::runtime_error("checkpoint: outflow records differ");
  r_.outflow.clear();
  for (std::size_t k = 0; k < out_t.size(); ++k)
    r_.outflow.push_back({out_t[k], out_c[k], out_m[k]});
  rd.get(r_.filled_mass), rd.get(r_.discharged_mass), rd.get(r_.lost_mass);
  rd.get(r_.particles_filled), rd.get(r_.particles_lost);
}

DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress) {
  Discharge d(sim, g, valve_index, spec);
  d.open();
  return d.run(progress);
}

}  // namespace silodem
