// SPDX-License-Identifier: MIT
#include "io/report_json.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace silodem {

namespace {

// The numbers that per-coal contact tables set, as each pair kind uses them (after mixing).
struct PerCoalValue {
  std::string section, coal_a, coal_b, key;  // coal_b empty: a wall contact; key "slot.key"
  double value = 0.0;
};

std::vector<PerCoalValue> per_coal_values(const Case& c) {
  std::vector<PerCoalValue> out;
  const int n = int(c.coals.size());
  for (const auto* spec : {&c.particle_particle, &c.particle_wall}) {
    if (spec->per_coal.empty()) continue;
    const bool wall = spec == &c.particle_wall;
    for (int a = 0; a < n; ++a)
      for (int b = wall ? -1 : a; b < (wall ? 0 : n); ++b) {
        const ContactSpec m = spec_for(*spec, a, b);
        const SlotChoice* slots[4] = {&m.normal, &m.tangential, &m.rolling, &m.cohesion};
        for (int s = 0; s < 4; ++s) {
          std::vector<std::string> keys;
          for (int q : {a, b})
            if (q >= 0)
              for (const auto& [key, x] : spec->per_coal[std::size_t(q)].slot[s].numbers)
                if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
          std::sort(keys.begin(), keys.end());
          for (const auto& key : keys)
            out.push_back(
                {wall ? "particle_wall" : "particle_particle", c.coals[std::size_t(a)].name,
                 b >= 0 ? c.coals[std::size_t(b)].name : std::string(),
                 std::string(slot_name(Slot(s))) + "." + key, slots[s]->values.number(key)});
        }
      }
  }
  return out;
}

}  // namespace

std::string case_report_json(const Case& c, const CaseReport& r) {
  toml::array materials;
  for (const auto& m : r.coals) {
    materials.push_back(toml::table{
        {"name", m.name},
        {"porosity", m.measured.porosity},
        {"rumpf_porosity", m.measured.rumpf_porosity},
        {"tensile_strength_pa", m.measured.tensile_strength},
        {"cohesion_force_n", m.measured.cohesion_force},
        {"cohesion_force_cg_n", m.cohesion_cg},
        {"cg_diameter_m", m.cg_diameter},
        {"cg_mass_kg", m.cg_mass},
        {"particle_mass_kg", m.measured.particle_mass},
        {"bond_number", m.measured.bond_number},
        {"bond_number_cg", m.bond_number_cg},
        {"restitution_input", m.restitution_input},
        {"restitution_cg", m.restitution.value},
        {"restitution_policy", restitution_policy_name(c.cg.restitution_policy)},
        {"restitution_clamped", m.restitution.clamped},
        {"damping_normal", m.damping_normal},
        {"collision_time_s", m.collision_time},
        {"wall_damping_normal", m.wall_damping_normal},
        {"wall_collision_time_s", m.wall_collision_time},
    });
  }
  toml::array warnings;
  for (const auto& w : r.warnings) warnings.push_back(w);
  toml::array plan;
  for (const auto& sp : r.fill_plan)
    plan.push_back(toml::table{{"segment", sp.index},
                               {"coal", c.coals[std::size_t(sp.coal)].name},
                               {"z_low_m", sp.z_low},
                               {"z_high_m", sp.z_high},
                               {"volume_m3", sp.volume},
                               {"mass_kg", sp.mass}});
  toml::table root{
      {"case", c.path},
      {"materials", std::move(materials)},
      {"k", r.k},
      {"cohesion_exponent", c.cg.cohesion_exponent},
      {"collision_time_min_s", r.collision_time_min},
      {"time_step_s", r.time_step},
      {"steps_per_collision", r.collision_time_min / r.time_step},
      {"warnings", std::move(warnings)},
  };
  const auto per_coal = per_coal_values(c);
  if (!per_coal.empty()) {
    toml::array rows;
    for (const auto& v : per_coal) {
      toml::array coals{v.coal_a};
      if (!v.coal_b.empty()) coals.push_back(v.coal_b);
      rows.push_back(toml::table{
          {"section", v.section}, {"coals", std::move(coals)}, {"key", v.key}, {"value", v.value}});
    }
    root.insert("contact_per_coal", std::move(rows));
  }
  toml::array applied;
  for (const auto& v : r.cohesion_applied) {
    toml::array coals{c.coals[std::size_t(v.coal_a)].name};
    if (v.coal_b >= 0) coals.push_back(c.coals[std::size_t(v.coal_b)].name);
    applied.push_back(toml::table{{"section", v.coal_b < 0 ? "particle_wall" : "particle_particle"},
                                  {"coals", std::move(coals)},
                                  {"law", v.law},
                                  {"force_n", v.force}});
  }
  root.insert("cohesion_applied", std::move(applied));
  if (c.silo.present) {
    root.insert("fill_plan", std::move(plan));
    root.insert("inventory_calorific_kcal_kg", r.inventory_calorific);
  }
  std::ostringstream os;
  os << toml::json_formatter{root} << "\n";
  return os.str();
}

std::string case_report_text(const Case& c, const CaseReport& r) {
  std::string s = fmt::format("case {}{}\n", c.path, c.title.empty() ? "" : " - " + c.title);
  s += fmt::format("coarse graining k = {:g}, cohesion exponent {:g}, restitution policy {}\n", r.k,
                   c.cg.cohesion_exponent, restitution_policy_name(c.cg.restitution_policy));
  for (const auto& m : r.coals) {
    s += fmt::format("coal {}\n", m.name);
    s += fmt::format("  porosity (Eq. 15)            {:.4f}\n", m.measured.porosity);
    if (m.measured.rumpf_porosity != m.measured.porosity)
      s += fmt::format("  porosity in Eq. 14           {:.4f} (coarse_graining.rumpf_porosity)\n",
                       m.measured.rumpf_porosity);
    s += fmt::format("  tensile strength (Eq. 16)    {:.1f} Pa\n", m.measured.tensile_strength);
    s += fmt::format("  F_L (Eq. 14)                 {:.4e} N   Bond number {:.2f}\n",
                     m.measured.cohesion_force, m.measured.bond_number);
    s += fmt::format(
        "  F_L,cg = k^alpha F_L         {:.4e} N   Bond number {:.2f}"
        " (before cohesion.factor)\n",
        m.cohesion_cg, m.bond_number_cg);
    s += fmt::format("  CG diameter / mass           {:.4g} mm / {:.4e} kg\n", m.cg_diameter * 1e3,
                     m.cg_mass);
    s += fmt::format("  e_cg                         {:.4g}{}\n", m.restitution.value,
                     m.restitution.clamped ? " (clamped)" : "");
    s += fmt::format("  eta_n pair / wall            {:.4g} / {:.4g} N s/m\n", m.damping_normal,
                     m.wall_damping_normal);
    s += fmt::format("  t_col pair / wall            {:.4e} / {:.4e} s\n", m.collision_time,
                     m.wall_collision_time);
  }
  const auto per_coal = per_coal_values(c);
  if (!per_coal.empty()) {
    s += fmt::format("per-coal contact values (pairs of two coals: {} mean)\n",
                     c.particle_particle.mixing);
    for (const auto& v : per_coal)
      s +=
          fmt::format("  {} {:<28} {:<32} {:.6g}\n", v.section == "particle_wall" ? "wall" : "pair",
                      v.coal_b.empty() ? v.coal_a : v.coal_a + "-" + v.coal_b, v.key, v.value);
  }
  if (!r.cohesion_applied.empty()) {
    s += "moisture force per contact, as applied (cohesion.factor x F_L,cg: pair_rule between two "
         "coals, wall_factor at a wall)\n";
    for (const auto& v : r.cohesion_applied) {
      const std::string& a = c.coals[std::size_t(v.coal_a)].name;
      s += fmt::format("  {} {:<28} {:.4e} N  ({})\n", v.coal_b < 0 ? "wall" : "pair",
                       v.coal_b < 0 ? a : a + "-" + c.coals[std::size_t(v.coal_b)].name, v.force,
                       v.law);
    }
  }
  s += fmt::format("shortest collision t_col {:.4e} s; time step {:.4e} s; t_col / dt = {:.1f}\n",
                   r.collision_time_min, r.time_step, r.collision_time_min / r.time_step);
  if (c.silo.present) {
    s += fmt::format(
        "silo: outlet {:g} mm, cone {:g} mm to {:g} mm, half-angle {:.2f} deg; scenario {}\n",
        c.silo.geometry.outlet_diameter * 1e3, c.silo.geometry.cone_height * 1e3,
        c.silo.geometry.cylinder_diameter * 1e3,
        c.silo.geometry.half_angle() * 180.0 / 3.14159265358979323846, c.fill.scenario);
    double total = 0.0;
    bool known = true;  // every segment's coal has a measured bulk density
    for (const auto& sp : r.fill_plan) {
      const bool has = c.coals[std::size_t(sp.coal)].bulk_density > 0.0;
      known = known && has;
      s += fmt::format("  H{}  {:<12} z {:.4f}-{:.4f} m  {:.4f} m^3  {}\n", sp.index,
                       c.coals[std::size_t(sp.coal)].name, sp.z_low, sp.z_high, sp.volume,
                       has ? fmt::format("{:.3f} kg at the measured bulk density", sp.mass)
                           : std::string("(no measured bulk density: mass known after the fill)"));
      total += sp.mass;
    }
    if (known)
      s += fmt::format("  fill {:.3f} kg; inventory calorific value (Eq. 17) {:.1f} kcal/kg\n",
                       total, r.inventory_calorific);
    else
      s += "  fill mass and inventory calorific value known after the fill (fill.csv, "
           "summary.json)\n";
  }
  for (const auto& w : r.warnings) s += "warning: " + w + "\n";
  return s;
}

}  // namespace silodem
