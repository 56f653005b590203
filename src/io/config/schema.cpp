// SPDX-License-Identifier: MIT
#include "io/config/schema.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <stdexcept>

#include "core/constants.hpp"
#include "engine/walls/wall.hpp"
#include "model/contact/registry.hpp"

namespace silodem::config {

const std::vector<Section>& sections() {
  using F = Field;
  static const std::vector<Section> s = {
      {"simulation",
       "time stepping and global settings",
       false,
       {
           F::number("end_time", "simulated time to run", "s").with_default(1.0).above(0),
           F::number("time_step", "explicit time step; 0 = t_col,min / steps_per_collision", "s")
               .with_default(0.0)
               .at_least(0),
           F::number("steps_per_collision",
                     "N in dt = t_col,min / N (MFIX's DTSOLID_FACTOR default 50)")
               .with_default(50)
               .at_least(10)
               .at_most(1e6),
           F::vec3("gravity", "gravitational acceleration (default [0, 0, -9.81])", "m/s^2"),
           F::number("skin", "Verlet skin as a fraction of the smallest CG diameter")
               .with_default(0.25)
               .above(0)
               .at_most(5),
           F::integer("reorder_every",
                      "sort the particles along a Morton curve before every N-th neighbour-list "
                      "build, so that neighbours are close in memory (speed only: changes the "
                      "summation order, not the physics; 0 = never)")
               .with_default(10)
               .at_least(0)
               .at_most(1000000),
           F::integer("threads", "OpenMP threads; 0 = all cores")
               .with_default(0)
               .at_least(0)
               .at_most(1024),
           F::integer("seed", "seed of every random choice")
               .with_default(1)
               .at_least(0)
               .at_most(9.0e15),
           F::number("max_speed",
                     "guard: stop when a particle moves faster; 0 = derived (silo: "
                     "3 x the free-fall speed from the silo top to the sink + 1 m/s; generic "
                     "case: no bound)",
                     "m/s")
               .with_default(0)
               .at_least(0)
               .at_most(1e6),
           F::number("max_overlap",
                     "guard: stop when a contact overlaps by more than this "
                     "fraction of the smaller radius; 0 = off")
               .with_default(0.5)
               .at_least(0)
               .at_most(10),
           F::number("checkpoint_interval",
                     "simulated time between checkpoints of a silo run, "
                     "its fill and its discharge (checkpoint.bin; also written on SIGINT/SIGTERM); "
                     "0 = only on a signal",
                     "s")
               .with_default(10)
               .at_least(0)
               .at_most(1e6),
           F::number(
               "checkpoint_wall_interval",
               "wall-clock time between checkpoints of a silo run, whichever of the two comes "
               "first (a run killed without a signal loses about this at most); 0 = off",
               "s")
               .with_default(600)
               .at_least(0)
               .at_most(1e6),
       }},
      {"coarse_graining",
       "coarse-graining factor and scaling policies (PHYSICS.md 1)",
       false,
       {
           F::number("k", "each simulated sphere stands for k^3 particles; k = 1 is plain DEM")
               .with_default(1.0)
               .at_least(1)
               .at_most(100),
           F::number("cohesion_exponent", "alpha in F_L,cg = k^alpha F_L (paper: 3; Rumpf: 2)")
               .with_default(3.0)
               .at_least(2)
               .at_most(3),
           F::text("restitution_policy",
                   "e_cg: Eq. 11 (energy), Eq. 11 clamped to restitution_floor, or e unchanged",
                   {"energy", "energy-clamped", "none"}, "none"),
           F::number("restitution_floor", "e_min for energy-clamped")
               .with_default(0.01)
               .above(0)
               .at_most(1),
       }},
      {"coal",
       "a coal (or any granular material): measured properties (PHYSICS.md 4)",
       true,
       {
           F::text("name", "name used by particles, lattices and reports", {}),
           F::text("symbol",
                   "letter(s) used in scenario names such as \"L3-I2\" (default: first letter of "
                   "the name)",
                   {}, "-"),
           F::number("diameter_mm", "average particle diameter (the DEM size before k)", "mm",
                     units::mm)
               .needed()
               .above(0)
               .at_most(1e4),
           F::number("sauter_diameter_mm",
                     "Sauter mean diameter d_sv of Eq. 14 (default: diameter_mm)", "mm", units::mm)
               .above(0)
               .at_most(1e4),
           F::number("true_density_kg_m3", "particle (true) density", "kg/m^3")
               .needed()
               .above(0)
               .at_most(3e4),
           F::number("bulk_density_kg_m3", "measured bulk density (needed for cohesion)", "kg/m^3")
               .above(0)
               .at_most(3e4),
           F::number("cohesion_kpa",
                     "cohesion C of the yield locus (Table 1 says N; it is kPa, E1)", "kPa",
                     units::kPa)
               .at_least(0)
               .at_most(1e4),
           F::number("friction_angle_deg", "internal friction angle", "deg", units::deg)
               .above(0)
               .below(90),
           F::number("moisture_percent", "moisture content M", "%", units::percent)
               .at_least(0)
               .below(100),
           F::number("heating_value_kcal_kg", "lower heating value (Eq. 17)", "kcal/kg")
               .with_default(0.0)
               .at_least(0)
               .at_most(1e5),
           F::number("cohesion_force_n", "F_L of one original particle, replacing Eq. 14", "N")
               .at_least(0)
               .at_most(1e6),
           F::number_list("sieve_diameters_mm",
                          "size classes of a measured distribution (DEM sizes before k)", "mm",
                          units::mm)
               .above(0)
               .at_most(1e4),
           F::number_list("sieve_mass_fractions", "mass fraction of each size class (sum 1)")
               .at_least(0)
               .at_most(1),
       }},
      {"silo",
       "the laboratory silo (PHYSICS.md 5); its presence makes a silo case (fill + discharge). "
       "Defaults: the paper's silo",
       false,
       {
           F::number("outlet_diameter_mm", "outlet diameter", "mm", units::mm)
               .with_default(50)
               .above(0)
               .at_most(1e4),
           F::number("cone_height_mm", "height of the conical hopper", "mm", units::mm)
               .with_default(633)
               .above(0)
               .at_most(1e5),
           F::number("cylinder_diameter_mm", "diameter of the cylinder (top of the cone)", "mm",
                     units::mm)
               .with_default(468)
               .above(0)
               .at_most(1e5),
           F::number("cylinder_height_mm", "height of the cylinder above the cone", "mm", units::mm)
               .with_default(318)
               .at_least(0)
               .at_most(1e5),
           F::number("valve_gap_mm", "distance of the valve plate below the outlet", "mm",
                     units::mm)
               .with_default(0)
               .at_least(0)
               .at_most(1e3),
       }},
      {"fill",
       "layered filling (PHYSICS.md 5, E7, E13)",
       false,
       {
           F::text("scenario", "coals from the top down with their segment counts, e.g. \"L3-I2\"",
                   {}),
           F::integer("segments", "equal height segments of the fill height (H1 at the bottom)")
               .with_default(5)
               .at_least(1)
               .at_most(100),
           F::number("fill_height_mm", "height of the fill; 0 = the cone height (E7)", "mm",
                     units::mm)
               .with_default(0)
               .at_least(0)
               .at_most(1e5),
           F::text("mode",
                   "mass: each segment gets the measured bulk density x its volume; volume: settle "
                   "until the segment is full",
                   {"mass", "volume"}, "mass"),
           F::number("lattice_gap",
                     "inserted particles sit on a lattice of spacing d_max (1 + gap)")
               .with_default(0.05)
               .at_least(0.001)
               .at_most(1),
           F::number("settle_ke_per_particle_j",
                     "settled when the kinetic energy per particle is below this", "J")
               .with_default(1e-8)
               .above(0)
               .at_most(1),
           F::number("settle_max_time", "longest settling per segment", "s")
               .with_default(3)
               .above(0)
               .at_most(1e3),
       }},
      {"discharge",
       "the discharge after the valve opens",
       false,
       {
           F::number("bin", "outlet statistics bin (the paper: 1 s)", "s")
               .with_default(1)
               .at_least(1e-3)
               .at_most(1e3),
           F::number("sink_depth_mm", "particles this far below the outlet are counted and removed",
                     "mm", units::mm)
               .with_default(100)
               .above(0)
               .at_most(1e4),
           F::number("stall_time", "no outflow for this long = stopped flow (arching)", "s")
               .with_default(5)
               .above(0)
               .at_most(1e4),
           F::number("max_time", "longest discharge", "s").with_default(600).above(0).at_most(1e6),
           F::number("target_fraction", "discharged fraction of the filled mass that ends the run")
               .with_default(0.995)
               .above(0)
               .at_most(1),
       }},
      {"particle",
       "one particle placed explicitly",
       true,
       {
           F::text("coal", "coal name", {}),
           F::vec3("position", "centre", "m").needed(),
           F::vec3("velocity", "initial velocity", "m/s"),
           F::vec3("angular_velocity", "initial angular velocity", "rad/s"),
           F::number("diameter_mm", "simulated diameter (default: the coal's CG diameter)", "mm",
                     units::mm)
               .above(0)
               .at_most(1e5),
       }},
      {"lattice",
       "particles on a simple cubic lattice",
       true,
       {
           F::text("coal", "coal name", {}),
           F::vec3("origin", "centre of the first particle", "m").needed(),
           F::number("spacing", "centre-to-centre spacing", "m").needed().above(0),
           F::vec3("count", "particles along x, y, z").needed(),
           F::vec3("velocity", "initial velocity", "m/s"),
       }},
      {"output",
       "what `silodem run` writes",
       false,
       {
           F::integer("every", "steps between rows of trajectory.csv; 0 = initial and final state")
               .with_default(0)
               .at_least(0)
               .at_most(1e12),
           F::integer_list("ids", "particle ids to write; default all"),
           F::number("vtk_interval",
                     "simulated time between ParaView frames (particles_*.vtp "
                     "and particles.pvd) of a silo discharge; 0 = none (large for long runs)",
                     "s")
               .with_default(0)
               .at_least(0)
               .at_most(1e4),
           F::text("measured",
                   "CSV of measured outlet data (columns t_s and rate_kg_s and/or "
                   "calorific_kcal_kg), relative to the case file; drawn with the simulated "
                   "curves, errors in summary.json",
                   {})
               .optional(),
       }},
      {"probes",
       "observers of a silo discharge, each writing probe_<name>.csv into the run directory",
       false,
       {
           F::integer("every", "steps between samples; 0 = no probes")
               .with_default(1000)
               .at_least(0)
               .at_most(1e9),
           F::number_list("slab_times",
                          "times of the flow-pattern snapshots (default 0, 0.25, "
                          "0.5, 1, 2, 5, 10, 20, 40, 60, 80)",
                          "s")
               .at_least(0)
               .at_most(1e6),
           F::number("slab_thickness_mm",
                     "thickness of the vertical slab through the axis (the "
                     "snapshots and the velocity profiles)",
                     "mm", units::mm)
               .with_default(20)
               .above(0)
               .at_most(1e4),
           F::number_list("profile_heights_mm",
                          "heights above the outlet of the velocity "
                          "profiles (default 100, 200, 300)",
                          "mm", units::mm)
               .at_least(0)
               .at_most(1e5),
           F::number("profile_bin_mm", "width of the profile bins (and their height)", "mm",
                     units::mm)
               .with_default(10)
               .above(0)
               .at_most(1e4),
           F::number("profile_from", "start of the profiles' averaging window", "s")
               .with_default(0)
               .at_least(0)
               .at_most(1e6),
           F::number("profile_to", "end of the profiles' averaging window (default: the end)", "s")
               .with_default(1e9)
               .above(0)
               .at_most(1e9),
           F::number("adhesion_threshold",
                     "a particle is adhered when a partner's cohesive force "
                     "on it exceeds this",
                     "N")
               .with_default(1e-3)
               .at_least(0)
               .at_most(1e6),
           F::number("level_radius_mm",
                     "particles within this distance of the axis define the "
                     "material level",
                     "mm", units::mm)
               .with_default(20)
               .above(0)
               .at_most(1e4),
       }},
  };
  return s;
}

const Section& section(const std::string& name) {
  for (const auto& s : sections())
    if (s.name == name) return s;
  throw std::logic_error("no schema section " + name);
}

std::vector<std::string> top_level_keys() {
  return {"title", "simulation", "coarse_graining", "coal",   "contact",
          "wall",  "particle",   "lattice",         "output", "silo",
          "fill",  "discharge",  "probes"};
}

static std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(3, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

static std::string field_row(const Field& f) {
  std::string type;
  switch (f.kind) {
    case FieldKind::Number:
      type = "number";
      break;
    case FieldKind::Integer:
      type = "integer";
      break;
    case FieldKind::Bool:
      type = "bool";
      break;
    case FieldKind::String:
      type = "string";
      break;
    case FieldKind::Vec3:
      type = "[x, y, z]";
      break;
    case FieldKind::IntegerList:
      type = "[integers]";
      break;
    case FieldKind::NumberList:
      type = "[numbers]";
      break;
  }
  std::string def;
  if (f.required)
    def = "**required**";
  else if (f.kind == FieldKind::String)
    def = f.default_string.empty() ? "-" : "`\"" + f.default_string + "\"`";
  else if (f.kind == FieldKind::Bool)
    def = f.default_number && *f.default_number != 0 ? "`true`" : "`false`";
  else if (f.default_number)
    def = fmt::format("`{:g}`", *f.default_number);
  else
    def = "-";
  std::string range;
  if (!f.choices.empty()) {
    for (const auto& c : f.choices) range += (range.empty() ? "" : ", ") + ("`" + c + "`");
  } else if (f.kind == FieldKind::Number || f.kind == FieldKind::Integer ||
             f.kind == FieldKind::NumberList) {
    range = f.range_text();
  }
  std::string doc;  // a '|' in the text would end the table cell
  for (char ch : f.doc) doc += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", f.key, type,
                     f.unit.empty() ? "-" : f.unit, def, range.empty() ? "-" : range, doc);
}

static const char* kHeader =
    "| key | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n";

std::string markdown() {
  std::string md =
      "# Case file reference\n\n"
      "Generated by `silodem config-docs` from the schema in src/io/config/schema.cpp and the law\n"
      "and wall tables; do not edit by hand. Units are part of the key name where they are not "
      "SI.\n"
      "Unknown keys are refused with a suggestion; every error names file:line:column.\n\n"
      "Top-level keys: `" +
      fmt::format("{}", fmt::join(top_level_keys(), "`, `")) + "` (`title` is a string).\n";
  for (const auto& s : sections()) {
    md += fmt::format("\n## {}{}{}\n\n{}\n\n", s.array ? "[[" : "[", s.name, s.array ? "]]" : "]",
                      s.doc);
    md += kHeader;
    for (const auto& f : s.fields) md += field_row(f);
  }
  md +=
      "\n## [contact.particle_particle] and [contact.particle_wall]\n\n"
      "Four slots, each an inline table `{ law = \"...\", ... }`: `normal` (required), "
      "`tangential`, `rolling`, `cohesion` (default `none`). Laws and their keys:\n";
  for (Slot slot : {Slot::Normal, Slot::Tangential, Slot::Rolling, Slot::Cohesion}) {
    for (const auto& e : contact_laws()) {
      if (e.slot != slot) continue;
      md += fmt::format("\n### {} = \"{}\"\n\n{}\n\n", slot_name(slot), e.name, e.summary);
      auto pp = e.fields(false), pw = e.fields(true);
      if (pp.empty() && pw.empty()) {
        md += "No parameters.\n";
        continue;
      }
      md += kHeader;
      for (const auto& f : pp) md += field_row(f);
      for (const auto& f : pw)
        if (std::none_of(pp.begin(), pp.end(), [&](const Field& g) { return g.key == f.key; }))
          md += field_row(f).replace(0, 1, "| (particle_wall only) ");
    }
  }
  md += "\n## [[wall]]\n\n`type` selects the shape:\n";
  for (const auto& w : wall_types()) {
    md += fmt::format("\n### type = \"{}\"\n\n{}\n\n", w.name, w.summary);
    md += kHeader;
    for (const auto& f : w.fields()) md += field_row(f);
  }
  return md;
}

}  // namespace silodem::config
