// SPDX-License-Identifier: MIT
#include "engine/plate.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/bytes.hpp"
#include "engine/simulation.hpp"
#include "engine/walls/plane.hpp"

namespace silodem {

Plate::Plate(Simulation& sim, std::size_t wall, const std::vector<std::size_t>& glued)
    : wall_(wall) {
  const auto* plane = dynamic_cast<const PlaneWall*>(&sim.wall(wall));
  if (!plane) throw std::logic_error("Plate: the wall must be a plane");
  normal_ = plane->normal();
  glue(sim, glued);
}

void Plate::glue(Simulation& sim, const std::vector<std::size_t>& glued) {
  find_glued(sim);
  auto& p = sim.particles();
  for (std::size_t i : glued) {
    if (i >= p.size()) throw std::logic_error("Plate: no such particle");
    p.inv_mass[i] = 0.0;
    p.inv_inertia[i] = 0.0;
    p.omega[i] = Vec3{};
    p.v[i] = velocity_;
    ids_.push_back(p.id[i]);
    index_.push_back(i);
  }
}

void Plate::find_glued(const Simulation& sim) const {
  const auto& p = sim.particles();
  bool same = index_.size() == ids_.size();
  for (std::size_t k = 0; same && k < ids_.size(); ++k)
    same = index_[k] < p.size() && p.id[index_[k]] == ids_[k];
  if (same) return;
  // Reordered (or some removed): one pass over the ids.
  std::vector<std::pair<std::uint64_t, std::size_t>> by_id(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) by_id[i] = {p.id[i], i};
  std::sort(by_id.begin(), by_id.end());
  index_.clear();
  for (std::uint64_t id : ids_) {
    auto it = std::lower_bound(by_id.begin(), by_id.end(), std::make_pair(id, std::size_t(0)));
    if (it != by_id.end() && it->first == id) index_.push_back(it->second);
  }
}

Vec3 Plate::force(const Simulation& sim) const {
  find_glued(sim);
  const auto& p = sim.particles();
  const Vec3 g = sim.settings().gravity;
  Vec3 f = sim.wall_force(wall_);
  for (std::size_t i : index_) f += p.f[i] - g * p.mass[i] - p.f_ext[i];
  return f;
}

double Plate::load(const Simulation& sim) const {
  return -dot(force(sim), normal_);
}

void Plate::advance(Simulation& sim) {
  Vec3 v = control_.velocity;
  if (control_.servo) {
    const double target = control_.stress * control_.area;
    const double e = target - load(sim);
    const double ti = control_.integral_time;
    // along the normal: into the particles
    double vn = control_.gain * (e + (ti > 0 ? (integral_ + e * sim.dt()) / ti : 0.0));
    const bool capped = control_.max_speed > 0 && std::abs(vn) > control_.max_speed;
    if (capped) vn = std::clamp(vn, -control_.max_speed, control_.max_speed);
    if (ti > 0 && !capped) integral_ += e * sim.dt();
    v = v - normal_ * dot(v, normal_) + normal_ * vn;
  }
  velocity_ = v;
  const Vec3 d = v * sim.dt();
  Wall& w = sim.wall(wall_);
  w.translate(d);
  w.set_velocity(v);
  displacement_ += d;
  find_glued(sim);
  auto& p = sim.particles();
  for (std::size_t i : index_) p.v[i] = v;
  // The list takes the wall as a candidate of the particles within the skin of it at the build;
  // once the wall has moved a quarter of the skin, a particle that moved a quarter towards it
  // could reach it unlisted.
  if (sim.neighbors().builds != builds_seen_) {
    builds_seen_ = sim.neighbors().builds;
    moved_since_build_ = Vec3{};
  }
  moved_since_build_ += d;
  const double skin = sim.neighbors().skin;
  if (norm2(moved_since_build_) > 0.0625 * skin * skin) sim.request_rebuild();
}

void Plate::save(ByteWriter& w, const Simulation& sim) const {
  const auto& plane = dynamic_cast<const PlaneWall&>(*sim.walls().at(wall_));
  w.tag("PLAT");
  w.put(plane.point()), w.put(plane.velocity());
  w.put(ids_);
  const PlateControl& c = control_;  // field by field: no padding bytes in the file
  w.put(c.velocity), w.put(std::uint8_t(c.servo)), w.put(c.stress), w.put(c.area), w.put(c.gain);
  w.put(c.max_speed), w.put(c.integral_time);
  w.put(velocity_), w.put(displacement_), w.put(moved_since_build_);
  w.put(integral_), w.put(builds_seen_);
}

void Plate::load(ByteReader& r, Simulation& sim) {
  auto& plane = dynamic_cast<PlaneWall&>(sim.wall(wall_));
  r.tag("PLAT");
  plane.place(r.get<Vec3>());
  plane.set_velocity(r.get<Vec3>());
  r.get(ids_);
  PlateControl& c = control_;
  r.get(c.velocity), c.servo = r.get<std::uint8_t>() != 0, r.get(c.stress), r.get(c.area);
  r.get(c.gain), r.get(c.max_speed), r.get(c.integral_time);
  r.get(velocity_), r.get(displacement_), r.get(moved_since_build_);
  r.get(integral_), r.get(builds_seen_);
  index_.clear();  // found again from the ids
  find_glued(sim);
  if (index_.size() != ids_.size())
    throw std::runtime_error("checkpoint: a plate's glued particles are not in the simulation");
}

void Plate::add_to(Simulation& sim) {
  sim.add_hook({"plate", Phase::StepBegin, 1, [this](Simulation& s) { advance(s); }});
}

}  // namespace silodem
