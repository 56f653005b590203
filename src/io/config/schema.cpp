// SPDX-License-Identifier: MIT
#include "io/config/schema.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <stdexcept>

#include "engine/walls/wall.hpp"
#include "io/config/case.hpp"
#include "model/contact/registry.hpp"

namespace silodem::config {

const std::vector<Bound<OutputSpec>>& output_fields() {
  using F = Field;
  using S = OutputSpec;
  static const std::vector<Bound<S>> b = {
      bind(F::integer("every", "steps between rows of trajectory.csv; 0 = initial and final state")
               .at_least(0)
               .at_most(1e12),
           &S::every),
      bind<S>(F::integer_list("ids", "particle ids to write; default all"),
              [](S& s, const ParamValues& v) {
                for (double id : v.lists.at("ids")) s.ids.push_back(std::uint64_t(id));
              }),
      bind(F::number("vtk_interval",
                     "simulated time between ParaView frames (particles_*.vtp "
                     "and particles.pvd) of a silo discharge; 0 = none (large for long runs)",
                     "s")
               .at_least(0)
               .at_most(1e4),
           &S::vtk_interval),
      unbound<S>(F::text("measured",
                         "CSV of measured outlet data (columns t_s and rate_kg_s and/or "
                         "calorific_kcal_kg), relative to the case file; drawn with the simulated "
                         "curves, errors in summary.json",
                         {})
                     .optional()),
  };
  return b;
}

// The sections in the order of docs/config.md. Each section's keys are declared beside the spec
// they fill (bound to its members): scenario/case.cpp, model/coarse_graining.cpp,
// model/material.cpp, scenario/silo_geometry.cpp, probes/probe_spec.cpp, output_fields() above.
const std::vector<Section>& sections() {
  static const std::vector<Section> s = {
      {"simulation", "time stepping and global settings", false, fields_of(time_fields())},
      {"coarse_graining",
       "coarse-graining factor and scaling policies, and the porosity that turns the measured "
       "tensile strength into a contact force (PHYSICS.md 1, 3)",
       false, fields_of(coarse_graining_fields())},
      {"coal", "a coal (or any granular material): measured properties (PHYSICS.md 4)", true,
       fields_of(coal_fields())},
      {"silo",
       "the laboratory silo (PHYSICS.md 5); its presence makes a silo case (fill + discharge). "
       "Defaults: the paper's silo",
       false, fields_of(silo_fields())},
      {"fill", "layered filling (PHYSICS.md 5, E7, E13)", false, fields_of(fill_fields())},
      {"discharge", "the discharge after the valve opens", false, fields_of(discharge_fields())},
      {"particle", "one particle placed explicitly", true, fields_of(particle_fields())},
      {"lattice", "particles on a simple cubic lattice", true, fields_of(lattice_fields())},
      {"output", "what `silodem run` writes", false, fields_of(output_fields())},
      {"probes",
       "observers of a silo discharge, each writing probe_<name>.csv into the run directory", false,
       fields_of(probe_fields())},
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

Field contact_mixing_field() {
  return Field::text("mixing",
                     "a contact of two different coals takes, for each number that a "
                     "[contact.particle_particle.coal.NAME] table replaces, this mean of the two "
                     "coals' values (harmonic: MercuryDPM's default for mixed species)",
                     {"harmonic", "mean", "min"}, "harmonic");
}

static const char* kHeader =
    "| key | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n";

std::string markdown() {
  std::string md =
      "# Case file reference\n\n"
      "Generated by `silodem config-docs` from the field lists bound to each spec (listed in\n"
      "src/io/config/schema.cpp) and the law and wall tables; do not edit by hand. Units are part\n"
      "of the key name where they are not SI.\n"
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
      "`tangential`, `rolling`, `cohesion` (default `none`).\n\n"
      "**Per-coal values.** A table `[contact.particle_particle.coal.NAME]` (or\n"
      "`[contact.particle_wall.coal.NAME]`), NAME a `[[coal]]` name, holds slot tables of numbers\n"
      "that replace the section's in the contacts of that coal, e.g. `normal = {\n"
      "adhesion_stiffness = 2.5e4 }`. The laws stay the section's: only their numbers may differ.\n"
      "A wall contact takes its coal's values; a contact of two different coals takes, number by\n"
      "number, the `mixing` mean of the two coals' values (a coal without its own value gives the\n"
      "section's). On the command line: `--set\n"
      "contact.particle_particle.coal.NAME.normal.adhesion_stiffness=2.5e4` (`--set` splits keys\n"
      "at dots, so it cannot reach a coal whose name has one).\n\n";
  md += kHeader;
  md += field_row(contact_mixing_field()).replace(0, 1, "| (particle_particle only) ");
  md += "\nLaws and their keys:\n";
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
