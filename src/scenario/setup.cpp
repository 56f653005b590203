// SPDX-License-Identifier: MIT
#include "scenario/setup.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.hpp"
#include "engine/neighbor/cell_grid.hpp"
#include "scenario/layers.hpp"
#include "scenario/outlet_stats.hpp"
#include "scenario/size_distribution.hpp"

namespace silodem {
namespace {

struct Body {
  int coal;
  Vec3 x, v, omega;
  double diameter;
  SourcePlace place;
  std::string key;
};

std::vector<Body> bodies_of(const ScenarioCase& c) {
  std::vector<Body> out;
  for (const auto& p : c.particles) {
    const double d = p.diameter > 0 ? p.diameter : c.cg.diameter(c.coals[p.coal].diameter);
    out.push_back({p.coal, p.x, p.v, p.omega, d, p.place, p.key});
  }
  for (const auto& l : c.lattices) {
    const double d = c.cg.diameter(c.coals[l.coal].diameter);
    for (int iz = 0; iz < l.nz; ++iz)
      for (int iy = 0; iy < l.ny; ++iy)
        for (int ix = 0; ix < l.nx; ++ix)
          out.push_back({l.coal, l.origin + Vec3{ix * l.spacing, iy * l.spacing, iz * l.spacing},
                         l.v, Vec3{}, d, l.place, fmt::format("{}[{},{},{}]", l.key, ix, iy, iz)});
  }
  return out;
}

}  // namespace

CaseReport derive_case(const ScenarioCase& c, ContactModel* model_out) {
  CaseReport r;
  r.k = c.cg.k;
  std::vector<double> cohesion_cg;
  for (const auto& coal : c.coals) {
    CoalReport cr;
    cr.name = coal.name;
    cr.measured = derive(coal, c.cg.rumpf_porosity);
    cr.cg_diameter = c.cg.diameter(coal.diameter);
    cr.cg_mass = c.cg.mass(cr.measured.particle_mass);
    cr.cohesion_cg = c.cg.cohesion_force(cr.measured.cohesion_force);
    cr.bond_number_cg = cr.cohesion_cg / (cr.cg_mass * kGravity);
    cohesion_cg.push_back(cr.cohesion_cg);
    r.coals.push_back(cr);
  }
  ContactModel model =
      ContactModel::build(c.particle_particle, c.particle_wall, cohesion_cg, c.cg, &r.warnings);
  auto applied = [&](int a, int b, const ContactLaw& law) {
    const double f = applied_cohesion_force(law);
    if (!std::isnan(f)) r.cohesion_applied.push_back({a, b, law.law_names[int(Slot::Cohesion)], f});
  };
  for (int a = 0; a < model.materials(); ++a)
    for (int b = a; b < model.materials(); ++b) applied(a, b, model.pair(a, b));
  for (int a = 0; a < model.materials(); ++a) applied(a, -1, model.wall(a));

  // Sizes present: the coals' CG particles and any explicitly sized particle.
  std::vector<double> min_mass(c.coals.size(), 0.0), min_radius(c.coals.size(), 0.0);
  for (std::size_t a = 0; a < c.coals.size(); ++a) {
    const double d = SizeSampler(c.coals[a], c.cg).min_diameter();
    min_mass[a] = sphere_mass(d, c.coals[a].true_density);
    min_radius[a] = 0.5 * d;
  }
  for (const auto& p : c.particles)
    if (p.diameter > 0) {
      min_mass[p.coal] =
          std::min(min_mass[p.coal], sphere_mass(p.diameter, c.coals[p.coal].true_density));
      min_radius[p.coal] = std::min(min_radius[p.coal], 0.5 * p.diameter);
    }

  r.collision_time_min = 1e300;
  for (std::size_t a = 0; a < c.coals.size(); ++a) {
    auto& cr = r.coals[a];
    // The restitution the normal law uses after the CG policy (every normal law takes one).
    cr.restitution_input =
        spec_for(c.particle_particle, int(a), int(a)).normal.values.number("restitution");
    cr.restitution = restitution_cg(cr.restitution_input, c.cg);
    const double m_eff = effective_mass(cr.cg_mass, cr.cg_mass);
    const double r_cg = 0.5 * cr.cg_diameter;
    cr.damping_normal = normal_damping_coefficient(model.pair(int(a), int(a)), m_eff, 0.5 * r_cg);
    cr.collision_time =
        model.pair_collision_time(int(a), int(a), cr.cg_mass, cr.cg_mass, r_cg, r_cg);
    cr.wall_damping_normal = normal_damping_coefficient(model.wall(int(a)), cr.cg_mass, r_cg);
    cr.wall_collision_time = model.wall_collision_time(int(a), cr.cg_mass, r_cg);
    for (std::size_t b = 0; b < c.coals.size(); ++b)
      r.collision_time_min = std::min(
          r.collision_time_min, model.pair_collision_time(int(a), int(b), min_mass[a], min_mass[b],
                                                          min_radius[a], min_radius[b]));
    r.collision_time_min = std::min(r.collision_time_min,
                                    model.wall_collision_time(int(a), min_mass[a], min_radius[a]));
  }

  if (c.time.time_step > 0.0) {
    r.time_step = c.time.time_step;
    if (r.time_step > r.collision_time_min / 10.0)
      throw InputError(c.time.time_step_place, "simulation.time_step",
                       fmt::format("{:.4g} s is above t_col / 10 = {:.4g} s (t_col = {:.4g} s, the "
                                   "shortest collision); allowed range (0, {:.4g}] s",
                                   r.time_step, r.collision_time_min / 10.0, r.collision_time_min,
                                   r.collision_time_min / 10.0));
  } else {
    r.time_step = r.collision_time_min / c.time.steps_per_collision;
  }

  if (c.silo.present) {
    const SiloGeometry& g = c.silo.geometry;
    const std::vector<std::string> seg = segments_bottom_up(parse_scenario(c.fill.scenario));
    const double h =
        (c.fill.fill_height > 0 ? c.fill.fill_height : g.cone_height) / c.fill.segments;
    std::vector<double> mass_per_coal(c.coals.size(), 0.0), q;
    for (const auto& coal : c.coals) q.push_back(coal.heating_value);
    for (std::size_t s = 0; s < seg.size(); ++s) {
      SegmentPlan sp;
      sp.index = int(s) + 1;
      sp.coal = int(std::find(c.coal_symbols.begin(), c.coal_symbols.end(), seg[s]) -
                    c.coal_symbols.begin());
      sp.z_low = double(s) * h;
      sp.z_high = double(s + 1) * h;
      sp.volume = g.volume(sp.z_low, sp.z_high);
      sp.mass = c.coals[std::size_t(sp.coal)].bulk_density * sp.volume;
      mass_per_coal[std::size_t(sp.coal)] += sp.mass;
      r.fill_plan.push_back(sp);
      r.segment_coal.push_back(sp.coal);
    }
    // Unknown (NaN) if a coal in the silo has no measured bulk density (a dry case filled by
    // volume): the run then takes it from the filled masses.
    bool planned = true;
    for (int coal : r.segment_coal)
      planned = planned && c.coals[std::size_t(coal)].bulk_density > 0;
    r.inventory_calorific =
        planned ? mixture_calorific(mass_per_coal, q) : std::numeric_limits<double>::quiet_NaN();
    for (std::size_t a = 0; a < c.coals.size(); ++a) {
      const double ratio = g.outlet_diameter / SizeSampler(c.coals[a], c.cg).max_diameter();
      if (ratio < 6.0)
        r.warnings.push_back(fmt::format(
            "outlet / largest CG diameter of {} is {:.2f} < 6: at the edge where even dry spheres "
            "clog (about 5; PHYSICS.md, coarse-graining caution)",
            c.coals[a].name, ratio));
    }
  }
  if (model_out) *model_out = std::move(model);
  return r;
}

SimulationSettings settings_of(const ScenarioCase& c, const CaseReport& report, double d_min,
                               int threads_override) {
  SimulationSettings s;
  s.dt = report.time_step;
  s.gravity = c.time.gravity;
  s.skin = c.time.skin * d_min;
  s.skin_floor = c.time.skin_floor;
  s.reorder_every = c.time.reorder_every;
  s.threads = threads_override > 0 ? threads_override : c.time.threads;
  s.max_overlap = c.time.max_overlap;
  s.max_speed = c.time.max_speed;
  if (s.max_speed == 0.0 && c.silo.present) {
    // Nothing in a silo run falls further than from the top of the silo to the sink.
    const double g = std::max(norm(c.time.gravity), 1e-30);
    s.max_speed =
        3.0 * std::sqrt(2.0 * g * (c.silo.geometry.total_height() + c.discharge.sink_depth)) + 1.0;
  }
  return s;
}

namespace {

// The [[wall]] tables of a case.
void add_case_walls(Simulation& sim, const ScenarioCase& c) {
  for (const auto& w : c.walls)
    for (auto& surface : find_wall_type(w.type)->make(w.values)) sim.add_wall(std::move(surface));
}

}  // namespace

std::unique_ptr<Simulation> build_silo_simulation(const ScenarioCase& c, const CaseReport& report,
                                                  ContactModel model, std::size_t* valve_index,
                                                  int threads_override) {
  double d_min = 1e300;
  for (const auto& coal : c.coals) d_min = std::min(d_min, SizeSampler(coal, c.cg).min_diameter());
  auto sim = std::make_unique<Simulation>(std::move(model),
                                          settings_of(c, report, d_min, threads_override));
  SiloWalls walls = make_silo_walls(c.silo.geometry);
  const std::size_t first = sim->walls().size();
  for (auto& w : walls.walls) sim->add_wall(std::move(w));
  add_case_walls(*sim, c);
  if (valve_index) *valve_index = first + walls.valve_index;
  return sim;
}

std::unique_ptr<Simulation> build_simulation(const ScenarioCase& c, const CaseReport& report,
                                             ContactModel model, int threads_override) {
  double d_min = 1e300;
  for (const auto& cr : report.coals) d_min = std::min(d_min, cr.cg_diameter);
  std::vector<Body> bodies = bodies_of(c);
  for (const auto& b : bodies) d_min = std::min(d_min, b.diameter);
  auto sim = std::make_unique<Simulation>(std::move(model),
                                          settings_of(c, report, d_min, threads_override));
  add_case_walls(*sim, c);

  // Refuse overlapping placements (a cell grid keeps this linear in the particle count).
  std::vector<Vec3> xs;
  double d_max = 0.0;
  for (const auto& b : bodies) xs.push_back(b.x), d_max = std::max(d_max, b.diameter);
  CellGrid grid;
  grid.build(xs, std::max(d_max, 1e-12), 8 * xs.size() + 64);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    grid.for_each_near(bodies[i].x, [&](int jj) {
      const std::size_t j = std::size_t(jj);
      if (j >= i) return;
      const double dist = norm(bodies[i].x - bodies[j].x);
      const double contact = 0.5 * (bodies[i].diameter + bodies[j].diameter);
      if (dist < contact * (1.0 - 1e-9))
        throw InputError(bodies[i].place, bodies[i].key + ".position",
                         fmt::format("overlaps {} (centre distance {:.6g} m < sum of radii "
                                     "{:.6g} m); placed particles must not overlap",
                                     bodies[j].key, dist, contact));
    });
  }
  auto& p = sim->particles();
  for (const auto& b : bodies) {
    const double m = sphere_mass(b.diameter, c.coals[b.coal].true_density);
    p.add(b.x, b.v, b.omega, 0.5 * b.diameter, m, b.coal);
  }
  return sim;
}

}  // namespace silodem
