// SPDX-License-Identifier: MIT
#include "scenario/discharge.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace silodem {

const char* lost_reason_name(LostReason r) {
  switch (r) {
    case LostReason::OutsideWall:
      return "outside_wall";
    case LostReason::AboveSilo:
      return "above_silo";
    case LostReason::BelowOutsideOutlet:
      return "below_outside_outlet";
  }
  return "?";
}

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

void Discharge::note_crossings() {
  // A centre moves microns per step, far less than its radius, so each one going below z = 0 is
  // seen in the band of one radius under the plane (one that is not, e.g. below z = 0 when the
  // valve opened, is classified where the next check finds it).
  const auto& p = sim_.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z = p.x[i].z;
    if (z >= 0.0 || z < -p.radius[i]) continue;
    if (!crossed_.count(p.id[i])) entered_.emplace(p.id[i], std::hypot(p.x[i].x, p.x[i].y));
  }
}

void Discharge::add_lost(double t, std::size_t i, LostReason why, double crossing_r) {
  const auto& p = sim_.particles();
  const bool valve_closed = sim_.walls()[valve_]->enabled;
  r_.lost.push_back({t, p.id[i], p.material[i], p.x[i], p.v[i], p.radius[i], p.mass[i], why,
                     g_.nearest_surface(p.x[i], valve_closed), crossing_r});
  r_.lost_mass += p.mass[i];
  ++r_.particles_lost;
}

void Discharge::check(double t, std::vector<std::size_t>& remove) {
  auto& p = sim_.particles();
  remove.clear();
  auto discharged = [&](std::size_t i, double t_out) { book_out(t, i, t_out, remove); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z = p.x[i].z;
    const double r_xy = std::hypot(p.x[i].x, p.x[i].y);
    auto c = crossed_.find(p.id[i]);
    if (z < 0.0 && c == crossed_.end()) {
      // Left through the outlet, or past the rim outside it (escaped: lost): where its centre
      // crossed z = 0 decides. Not seen crossing: where it is now, its radius the margin.
      const auto e = entered_.find(p.id[i]);
      const bool seen = e != entered_.end();
      const double r_cross = seen ? e->second : r_xy;
      const bool inside = r_cross <= g_.outlet_radius() + (seen ? 0.0 : p.radius[i]);
      c = crossed_.emplace(p.id[i], Crossing{inside ? t : -1.0, r_cross}).first;
      if (seen) entered_.erase(e);
    }
    const double r_cross =
        c != crossed_.end() ? c->second.r : std::numeric_limits<double>::quiet_NaN();
    if (z > g_.total_height() + 0.5) {
      add_lost(t, i, LostReason::AboveSilo, r_cross);
      remove.push_back(i);
    } else if (z >= 0.0 && r_xy > g_.radius_at(z) + p.radius[i]) {
      if (c != crossed_.end() && c->second.t >= 0.0) {
        // Out through the outlet and back up outside the cone, round the rim: discharged.
        discharged(i, c->second.t);
        ++r_.particles_round_rim;
      } else {
        add_lost(t, i, LostReason::OutsideWall, r_cross);
        remove.push_back(i);
      }
    } else if (z < -spec_.sink_depth) {
      if (c->second.t < 0.0) {
        add_lost(t, i, LostReason::BelowOutsideOutlet, r_cross);
        remove.push_back(i);
      } else {
        discharged(i, c->second.t);
      }
    }
  }
  for (std::size_t i : remove) crossed_.erase(p.id[i]), entered_.erase(p.id[i]);
  sim_.remove_particles(remove);
}

void Discharge::book_out(double t, std::size_t i, double t_out, std::vector<std::size_t>& remove) {
  const auto& p = sim_.particles();
  r_.outflow.push_back({t_out, p.material[i], p.mass[i]});
  r_.discharged_mass += p.mass[i];
  bin_mass_ += p.mass[i];
  last_out_ = t;
  remove.push_back(i);
}

void Discharge::book_in_flight(double t, double t_cap, std::vector<std::size_t>& remove) {
  auto& p = sim_.particles();
  remove.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.x[i].z >= 0.0) continue;
    const auto c = crossed_.find(p.id[i]);  // check() has just classified every centre below 0
    if (c == crossed_.end()) continue;
    if (c->second.t < 0.0) {
      // Crossed outside the outlet, past the rim: lost, as the sink would have found it.
      add_lost(t, i, LostReason::BelowOutsideOutlet, c->second.r);
      remove.push_back(i);
    } else if (p.x[i].z < -p.radius[i] && p.v[i].z < 0.0) {
      // Wholly below the outlet plane and moving down: it has left the silo. One still within a
      // radius of the plane, or not moving down, may hang from the bed and stays in the silo.
      book_out(t, i, std::min(c->second.t, t_cap), remove);
    }
  }
  for (std::size_t i : remove) crossed_.erase(p.id[i]), entered_.erase(p.id[i]);
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
        note_crossings();
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
        book_in_flight(t, std::numeric_limits<double>::infinity(), remove);
        r_.end = DischargeEnd::Emptied;
        break;
      }
      if (t - std::max(last_out_, fall_) >= spec_.stall_time) {
        r_.end = DischargeEnd::FlowStopped;
        break;
      }
      if (t >= spec_.max_time) {
        // The last check is at or just after max_time: what it first saw below the plane is booked
        // at max_time, in the last bin, not in a sliver bin after it.
        book_in_flight(t, spec_.max_time, remove);
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
  std::vector<double> times, radii;
  for (const auto& [id, c] : crossed_)
    ids.push_back(id), times.push_back(c.t), radii.push_back(c.r);
  w.put(ids), w.put(times);
  std::vector<double> out_t, out_m;
  std::vector<int> out_c;
  for (const auto& o : r_.outflow)
    out_t.push_back(o.t), out_c.push_back(o.coal), out_m.push_back(o.mass);
  w.put(out_t), w.put(out_c), w.put(out_m);
  w.put(r_.filled_mass), w.put(r_.discharged_mass), w.put(r_.lost_mass);
  w.put(r_.particles_filled), w.put(r_.particles_lost);
  // Since lost.csv: where each crossed, the crossings not yet checked, the lost records. A
  // section of its own, so that a checkpoint written before it still loads.
  w.tag("LOST");
  w.put(radii);
  std::vector<std::uint64_t> e_ids;
  std::vector<double> e_r;
  for (const auto& [id, r] : entered_) e_ids.push_back(id), e_r.push_back(r);
  w.put(e_ids), w.put(e_r);
  w.put(r_.particles_round_rim);
  std::vector<double> t, radius, mass, distance, crossing_r;
  std::vector<std::uint64_t> id;
  std::vector<int> coal;
  std::vector<Vec3> x, v;
  std::vector<std::uint8_t> reason, surface;
  for (const auto& l : r_.lost) {
    t.push_back(l.t), id.push_back(l.id), coal.push_back(l.coal), x.push_back(l.x);
    v.push_back(l.v), radius.push_back(l.radius), mass.push_back(l.mass);
    reason.push_back(std::uint8_t(l.reason)), surface.push_back(std::uint8_t(l.nearest.surface));
    distance.push_back(l.nearest.distance), crossing_r.push_back(l.crossing_r);
  }
  w.put(t), w.put(id), w.put(coal), w.put(x), w.put(v), w.put(radius), w.put(mass);
  w.put(reason), w.put(surface), w.put(distance), w.put(crossing_r);
}

void Discharge::load(ByteReader& rd) {
  rd.tag("DISC");
  rd.get(t0_), rd.get(steps0_), rd.get(step_in_interval_), rd.get(next_checkpoint_);
  rd.get(last_out_), rd.get(bin_mass_), rd.get(bin_start_), rd.get(recent_rate_);
  std::vector<std::uint64_t> ids;
  std::vector<double> times;
  rd.get(ids), rd.get(times);
  if (ids.size() != times.size()) throw std::runtime_error("checkpoint: discharge records differ");
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
  std::vector<double> radii(ids.size(), std::numeric_limits<double>::quiet_NaN());
  entered_.clear();
  r_.lost.clear();
  r_.particles_round_rim = 0;
  if (rd.next_is("LOST")) {  // (a checkpoint from before lost.csv has none of this)
    rd.tag("LOST");
    rd.get(radii);
    if (radii.size() != ids.size()) throw std::runtime_error("checkpoint: crossings differ");
    std::vector<std::uint64_t> e_ids;
    std::vector<double> e_r;
    rd.get(e_ids), rd.get(e_r);
    if (e_r.size() != e_ids.size()) throw std::runtime_error("checkpoint: crossings differ");
    for (std::size_t k = 0; k < e_ids.size(); ++k) entered_[e_ids[k]] = e_r[k];
    rd.get(r_.particles_round_rim);
    std::vector<double> t, radius, mass, distance, crossing_r;
    std::vector<std::uint64_t> id;
    std::vector<int> coal;
    std::vector<Vec3> x, v;
    std::vector<std::uint8_t> reason, surface;
    rd.get(t), rd.get(id), rd.get(coal), rd.get(x), rd.get(v), rd.get(radius), rd.get(mass);
    rd.get(reason), rd.get(surface), rd.get(distance), rd.get(crossing_r);
    const std::size_t n = t.size();
    for (std::size_t size : {id.size(), coal.size(), x.size(), v.size(), radius.size(), mass.size(),
                             reason.size(), surface.size(), distance.size(), crossing_r.size()})
      if (size != n) throw std::runtime_error("checkpoint: lost records differ");
    for (std::size_t k = 0; k < n; ++k) {
      if (reason[k] > std::uint8_t(LostReason::BelowOutsideOutlet) ||
          surface[k] > std::uint8_t(SiloSurface::Valve))
        throw std::runtime_error("checkpoint: lost records damaged");
      const SurfaceDistance nearest{SiloSurface(surface[k]), distance[k]};
      r_.lost.push_back({t[k], id[k], coal[k], x[k], v[k], radius[k], mass[k],
                         LostReason(reason[k]), nearest, crossing_r[k]});
    }
  }
  crossed_.clear();
  for (std::size_t k = 0; k < ids.size(); ++k) crossed_[ids[k]] = {times[k], radii[k]};
}

DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress) {
  Discharge d(sim, g, valve_index, spec);
  d.open();
  return d.run(progress);
}

}  // namespace silodem
