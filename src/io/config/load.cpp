// SPDX-License-Identifier: MIT
#include "io/config/load.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/walls/wall.hpp"
#include "io/config/schema.hpp"
#include "io/measured.hpp"
#include "model/contact/registry.hpp"
#include "scenario/layers.hpp"

namespace silodem::config {
namespace {

// A TOML number (integer or float) as a double. toml++'s value<double>() of an integer is empty
// unless the double is exact, so an integer beyond 2^53 (7788888888888888888, found by the
// fuzzer) would throw bad_optional_access: it is rounded instead, and the range check refuses it.
double number_of(const toml::node& n) {
  if (const auto* i = n.as_integer()) return double(i->get());
  return n.value<double>().value();
}

struct Reader {
  std::string file;

  SourcePlace place(const toml::node& n) const {
    const auto& s = n.source();
    // Values from --set overrides carry their own "path" ("--set key=value").
    return {s.path && !s.path->empty() ? *s.path : file, int(s.begin.line), int(s.begin.column)};
  }

  std::string type_name(FieldKind k) const {
    switch (k) {
      case FieldKind::Number:
        return "a number";
      case FieldKind::Integer:
        return "an integer";
      case FieldKind::Bool:
        return "true or false";
      case FieldKind::String:
        return "a string";
      case FieldKind::Vec3:
        return "an array of 3 numbers";
      case FieldKind::IntegerList:
        return "an array of integers";
      case FieldKind::NumberList:
        return "an array of numbers";
    }
    return "?";
  }

  static std::string show(const toml::node& n) {
    std::ostringstream os;
    if (n.is_table()) return "a table";
    if (n.is_integer()) return fmt::format("{}", n.value<std::int64_t>().value());
    if (n.is_floating_point()) return fmt::format("{}", n.value<double>().value());
    if (n.is_array()) {
      os << *n.as_array();
      return os.str();
    }
    os << toml::node_view<const toml::node>(n);
    return os.str();
  }

  // Validates table `t` against `fields` (plus `extra_keys` that the caller reads itself).
  ParamValues read(const toml::table& t, const std::vector<Field>& fields,
                   const std::string& section, const std::vector<std::string>& extra_keys = {}) {
    ParamValues v;
    v.section = section;
    v.place = place(t);
    std::vector<std::string> known = extra_keys;
    for (const auto& f : fields) known.push_back(f.key);
    for (const auto& [k, node] : t) {
      const std::string key(k.str());
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      const std::string hint = did_you_mean(key, known);
      // In a contact-law table the keys depend on the law: a --set that changes only `law` leaves
      // the old law's keys behind, so say how to replace the table.
      const auto law = t["law"].value<std::string>();
      const std::string of_law =
          law ? fmt::format(
                    " (the keys of law '{}'; to change the law, replace the whole table: "
                    "--set '{}={{ law = \"{}\" }}')",
                    *law, section, *law)
              : "";
      throw InputError(place(node), section.empty() ? key : section + "." + key,
                       hint.empty() ? fmt::format("unknown key; allowed here: {}{}",
                                                  fmt::join(known, ", "), of_law)
                                    : fmt::format("unknown key; did you mean '{}'?", hint));
    }
    for (const auto& f : fields) {
      const toml::node* node = t.get(f.key);
      const std::string full = section.empty() ? f.key : section + "." + f.key;
      if (!node) {
        if (f.required) throw InputError(v.place, full, "missing required key (" + f.doc + ")");
        v.given[f.key] = false;
        switch (f.kind) {
          case FieldKind::String:
            v.strings[f.key] = f.default_string;
            break;
          case FieldKind::Vec3:
            v.vectors[f.key] = Vec3{};
            break;
          case FieldKind::IntegerList:
          case FieldKind::NumberList:
            v.lists[f.key] = {};
            break;
          default:
            if (f.default_number) v.numbers[f.key] = *f.default_number * f.to_si;
        }
        continue;
      }
      v.given[f.key] = true;
      const SourcePlace at = place(*node);
      v.places[f.key] = at;
      auto bad_type = [&]() {
        return InputError(at, full, fmt::format("= {} must be {}", show(*node), type_name(f.kind)));
      };
      auto check_number = [&](double x) {
        if (!f.in_range(x))
          throw InputError(at, full,
                           fmt::format("= {} is out of range; allowed {}{}", show(*node),
                                       f.range_text(), f.unit.empty() ? "" : " " + f.unit));
        return x * f.to_si;
      };
      switch (f.kind) {
        case FieldKind::Number: {
          if (!node->is_number()) throw bad_type();
          v.numbers[f.key] = check_number(number_of(*node));
          break;
        }
        case FieldKind::Integer: {
          if (!node->is_integer()) throw bad_type();
          v.numbers[f.key] = check_number(double(node->value<std::int64_t>().value()));
          break;
        }
        case FieldKind::Bool:
          if (!node->is_boolean()) throw bad_type();
          v.numbers[f.key] = node->value<bool>().value() ? 1.0 : 0.0;
          break;
        case FieldKind::String: {
          if (!node->is_string()) throw bad_type();
          std::string s = node->value<std::string>().value();
          if (!f.choices.empty() &&
              std::find(f.choices.begin(), f.choices.end(), s) == f.choices.end()) {
            const std::string hint = did_you_mean(s, f.choices);
            throw InputError(at, full,
                             fmt::format("= \"{}\" is not allowed; choose one of: {}{}", s,
                                         fmt::join(f.choices, ", "),
                                         hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
          }
          if (s.empty()) throw InputError(at, full, "must not be empty");
          v.strings[f.key] = std::move(s);
          break;
        }
        case FieldKind::Vec3: {
          const toml::array* a = node->as_array();
          if (!a || a->size() != 3) throw bad_type();
          double c[3];
          for (int i = 0; i < 3; ++i) {
            if (!(*a)[i].is_number()) throw bad_type();
            c[i] = number_of((*a)[i]);
            if (!std::isfinite(c[i])) throw InputError(at, full, "components must be finite");
            c[i] *= f.to_si;
          }
          v.vectors[f.key] = {c[0], c[1], c[2]};
          break;
        }
        case FieldKind::IntegerList: {
          const toml::array* a = node->as_array();
          if (!a) throw bad_type();
          std::vector<double> out;
          for (const auto& e : *a) {
            if (!e.is_integer() || e.value<std::int64_t>().value() < 0) throw bad_type();
            out.push_back(double(e.value<std::int64_t>().value()));
          }
          v.lists[f.key] = std::move(out);
          break;
        }
        case FieldKind::NumberList: {
          const toml::array* a = node->as_array();
          if (!a || a->empty()) throw bad_type();
          std::vector<double> out;
          for (const auto& e : *a) {
            if (!e.is_number()) throw bad_type();
            const double x = number_of(e);
            if (!f.in_range(x))
              throw InputError(place(e), full,
                               fmt::format("contains {} which is out of range; allowed {}{}", x,
                                           f.range_text(), f.unit.empty() ? "" : " " + f.unit));
            out.push_back(x * f.to_si);
          }
          v.lists[f.key] = std::move(out);
          break;
        }
      }
    }
    return v;
  }

  // Validates table `t` against the keys bound to S's members and stores the given ones in `s`.
  template <class S>
  ParamValues read_into(S& s, const toml::table& t, const std::vector<Bound<S>>& bound,
                        const std::string& section) {
    ParamValues v = read(t, fields_of(bound), section);
    assign(s, bound, v);
    return v;
  }

  const toml::table& table_at(const toml::node& n, const std::string& key) {
    if (!n.is_table()) throw InputError(place(n), key, "must be a table");
    return *n.as_table();
  }

  // [[name]] or a single [name] table -> list of tables.
  std::vector<const toml::table*> tables(const toml::table& root, const std::string& key) {
    std::vector<const toml::table*> out;
    const toml::node* n = root.get(key);
    if (!n) return out;
    if (n->is_table()) return {n->as_table()};
    const toml::array* a = n->as_array();
    if (!a) throw InputError(place(*n), key, "must be [[" + key + "]] tables");
    for (const auto& e : *a) {
      if (!e.is_table()) throw InputError(place(e), key, "must be [[" + key + "]] tables");
      out.push_back(e.as_table());
    }
    return out;
  }

  SlotChoice slot(const toml::table& contact, const std::string& section, Slot s, bool wall) {
    const std::string key = slot_name(s);
    const std::string full = section + "." + key;
    const toml::node* n = contact.get(key);
    SlotChoice c;
    if (!n) {
      if (s == Slot::Normal)
        throw InputError(place(contact), full,
                         "missing required slot (e.g. { law = \"linear_spring_dashpot\", stiffness "
                         "= 1e5, restitution = 0.1 })");
      c.law = "none";
      c.values.section = full;
      c.values.place = place(contact);
      return c;
    }
    const toml::table& t = table_at(*n, full);
    const toml::node* law = t.get("law");
    const auto names = law_names(s);
    if (!law || !law->is_string())
      throw InputError(
          place(t), full + ".law",
          fmt::format("missing or not a string; choose one of: {}", fmt::join(names, ", ")));
    c.law = law->value<std::string>().value();
    const LawEntry* e = find_law(s, c.law);
    if (!e) {
      const std::string hint = did_you_mean(c.law, names);
      throw InputError(place(*law), full + ".law",
                       fmt::format("= \"{}\" is not a {} law; choose one of: {}{}", c.law, key,
                                   fmt::join(names, ", "),
                                   hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    c.values = read(t, e->fields(wall), full, {"law"});
    return c;
  }

  // [contact.<which>.coal.<name>]: per coal, numbers of the section's laws that replace its
  // values in that coal's contacts (ContactSpec::per_coal).
  std::vector<CoalContactValues> per_coal(const toml::node& n, const std::string& section,
                                          const ContactSpec& spec,
                                          const std::vector<std::string>& coals, bool wall) {
    const std::string where = section + ".coal";
    const toml::table& t = table_at(n, where);
    std::vector<CoalContactValues> out(coals.size());
    const SlotChoice* chosen[4] = {&spec.normal, &spec.tangential, &spec.rolling, &spec.cohesion};
    for (const auto& [k, node] : t) {
      const std::string name(k.str());
      const auto it = std::find(coals.begin(), coals.end(), name);
      if (it == coals.end()) {
        const std::string hint = did_you_mean(name, coals);
        throw InputError(
            place(node), where + "." + name,
            fmt::format("\"{}\" is not a [[coal]] name; known: {}{}", name, fmt::join(coals, ", "),
                        hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      const std::string sec = where + "." + name;
      const toml::table& ct = table_at(node, sec);
      CoalContactValues& cv = out[std::size_t(it - coals.begin())];
      for (const auto& [sk, snode] : ct) {
        const std::string key(sk.str());
        int s = -1;
        for (int q = 0; q < 4; ++q)
          if (key == slot_name(Slot(q))) s = q;
        if (s < 0) {
          const std::string hint =
              did_you_mean(key, {"normal", "tangential", "rolling", "cohesion"});
          throw InputError(
              place(snode), sec + "." + key,
              "unknown slot" + (hint.empty() ? "; slots are normal, tangential, rolling, cohesion"
                                             : "; did you mean '" + hint + "'?"));
        }
        const std::string full = sec + "." + key;
        const toml::table& st = table_at(snode, full);
        if (const toml::node* law = st.get("law"))
          throw InputError(place(*law), full + ".law",
                           fmt::format("a coal cannot change the law (\"{}\" for every coal, "
                                       "set in [{}]); only its numbers may differ per coal",
                                       chosen[s]->law, section));
        // The numbers of the section's law, none required and none defaulted.
        std::vector<Field> fields;
        std::vector<std::string> others;  // its keys that are not numbers
        for (Field f : find_law(Slot(s), chosen[s]->law)->fields(wall)) {
          if (f.kind != FieldKind::Number) {
            others.push_back(f.key);
            continue;
          }
          f.required = false;
          f.default_number.reset();
          fields.push_back(std::move(f));
        }
        if (fields.empty() && !st.empty())
          throw InputError(place(snode), full,
                           fmt::format("the {} law of [{}] is \"{}\", which has no numbers to set "
                                       "per coal",
                                       key, section, chosen[s]->law));
        for (const auto& [ok, onode] : st)
          if (std::find(others.begin(), others.end(), std::string(ok.str())) != others.end())
            throw InputError(
                place(onode), full + "." + std::string(ok.str()),
                "cannot differ per coal: only numbers can (set it in [" + section + "])");
        ParamValues v = read(st, fields, full);
        for (auto g = v.numbers.begin(); g != v.numbers.end();)
          g = v.was_given(g->first) ? std::next(g) : v.numbers.erase(g);
        cv.slot[s] = std::move(v);
      }
    }
    bool any = false;
    for (const auto& cv : out) any = any || !cv.empty();
    if (!any) out.clear();
    return out;
  }

  ContactSpec contact(const toml::table& root, const std::string& which, bool wall,
                      const std::vector<std::string>& coals) {
    const std::string section = "contact." + which;
    const toml::node* cn = root.get("contact");
    if (!cn)
      throw InputError({file, 1, 1}, "contact", "missing required section [contact." + which + "]");
    const toml::table& ct = table_at(*cn, "contact");
    const toml::node* n = ct.get(which);
    if (!n) throw InputError(place(ct), section, "missing required section [" + section + "]");
    const toml::table& t = table_at(*n, section);
    for (const auto& [k, node] : t) {
      const std::string key(k.str());
      const std::vector<std::string> slots = {"normal", "tangential", "rolling", "cohesion"};
      if (key == "coal" || (key == "mixing" && !wall)) continue;
      if (std::find(slots.begin(), slots.end(), key) == slots.end()) {
        std::vector<std::string> known = slots;
        known.push_back("coal");
        if (!wall) known.push_back("mixing");
        const std::string hint = did_you_mean(key, known);
        throw InputError(place(node), section + "." + key,
                         hint.empty() ? fmt::format("unknown key; allowed here: the slots normal, "
                                                    "tangential, rolling, cohesion, and {}",
                                                    wall ? "coal" : "coal, mixing")
                                      : "unknown key; did you mean '" + hint + "'?");
      }
    }
    ContactSpec spec;
    spec.normal = slot(t, section, Slot::Normal, wall);
    spec.tangential = slot(t, section, Slot::Tangential, wall);
    spec.rolling = slot(t, section, Slot::Rolling, wall);
    spec.cohesion = slot(t, section, Slot::Cohesion, wall);
    if (!wall)
      spec.mixing = read(t, {contact_mixing_field()}, section,
                         {"normal", "tangential", "rolling", "cohesion", "coal"})
                        .string("mixing");
    if (const toml::node* pc = t.get("coal")) {
      spec.per_coal = per_coal(*pc, section, spec, coals, wall);
      spec.coal_names = coals;
    }
    return spec;
  }
};

int coal_index(const Case& c, const ParamValues& v, const std::string& key) {
  const std::string& name = v.string(key);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < c.coals.size(); ++i) {
    if (c.coals[i].name == name) return int(i);
    names.push_back(c.coals[i].name);
  }
  const std::string hint = did_you_mean(name, names);
  throw v.error(
      key, fmt::format("= \"{}\" is not a [[coal]] name; known: {}{}", name, fmt::join(names, ", "),
                       hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

Case build(const toml::table& root, const std::string& file, const std::string& base_dir) {
  Reader r{file};
  Case c;
  c.path = file;
  const auto top = top_level_keys();
  for (const auto& [k, node] : root) {
    const std::string key(k.str());
    if (std::find(top.begin(), top.end(), key) != top.end()) continue;
    const std::string hint = did_you_mean(key, top);
    throw InputError(r.place(node), key,
                     hint.empty()
                         ? fmt::format("unknown section; allowed: {}", fmt::join(top, ", "))
                         : fmt::format("unknown section; did you mean '{}'?", hint));
  }
  if (const toml::node* t = root.get("title")) {
    if (!t->is_string()) throw InputError(r.place(*t), "title", "must be a string");
    c.title = t->value<std::string>().value();
  }

  static const toml::table empty;
  auto single = [&](const std::string& name) -> const toml::table& {
    const toml::node* n = root.get(name);
    return n ? r.table_at(*n, name) : empty;
  };

  // [simulation]
  {
    const ParamValues v = r.read_into(c.time, single("simulation"), time_fields(), "simulation");
    c.time.time_step_place = v.places.count("time_step") ? v.places.at("time_step") : v.place;
    c.time.steps_place = v.place;
  }
  // [coarse_graining]
  { r.read_into(c.cg, single("coarse_graining"), coarse_graining_fields(), "coarse_graining"); }
  // [[coal]]
  std::vector<std::string> missing_measured;  // per coal: the first Eq. 14-16 input not given
  const auto coal_tables = r.tables(root, "coal");
  if (coal_tables.empty())
    throw InputError({file, 1, 1}, "coal", "missing: at least one [[coal]] table is required");
  for (std::size_t i = 0; i < coal_tables.size(); ++i) {
    const std::string sec = fmt::format("coal[{}]", i);
    CoalProperties p;
    const ParamValues v = r.read_into(p, *coal_tables[i], coal_fields(), sec);
    for (const auto& other : c.coals)
      if (other.name == p.name) throw v.error("name", "= \"" + p.name + "\" is used by two coals");
    if (!v.was_given("sauter_diameter_mm")) p.sauter_diameter = p.diameter;
    // The measured inputs of Eq. 14-16 are needed only if a cohesion law uses the force: checked
    // after [contact.*] (a dry coal needs none of them).
    std::string missing;
    for (const char* key :
         {"bulk_density_kg_m3", "cohesion_kpa", "friction_angle_deg", "moisture_percent"})
      if (missing.empty() && !v.was_given(key)) missing = key;
    const bool measured_needed = !p.cohesion_force_override && missing.empty();
    missing_measured.push_back(p.cohesion_force_override ? std::string() : missing);
    if (v.was_given("bulk_density_kg_m3")) {
      if (p.bulk_density > p.true_density)
        throw v.error("bulk_density_kg_m3",
                      fmt::format("= {:g} is above true_density_kg_m3 = {:g}; allowed (0, {:g}] "
                                  "kg/m^3 (a bulk cannot be denser than its particles)",
                                  p.bulk_density, p.true_density, p.true_density));
    }
    if (measured_needed) {
      const double eps = porosity(p.bulk_density, p.true_density, p.moisture);
      if (!(eps > 0.0 && eps < 1.0))
        throw v.error("bulk_density_kg_m3",
                      fmt::format("gives a porosity (Eq. 15) of {:.4g}, outside (0, 1)", eps));
    }
    // Size distribution: class diameters and mass fractions, or one diameter.
    const auto& sd = v.lists.at("sieve_diameters_mm");
    const auto& sf = v.lists.at("sieve_mass_fractions");
    if (sd.size() != sf.size())
      throw v.error(sd.empty() ? "sieve_diameters_mm" : "sieve_mass_fractions",
                    fmt::format("sieve_diameters_mm has {} entries and sieve_mass_fractions {}; "
                                "give both, one entry per class",
                                sd.size(), sf.size()));
    if (!sd.empty()) {
      double sum = 0.0;
      for (std::size_t k = 0; k < sd.size(); ++k) {
        p.size_classes.push_back({sd[k], sf[k]});
        sum += sf[k];
      }
      if (std::fabs(sum - 1.0) > 1e-3)
        throw v.error("sieve_mass_fractions",
                      fmt::format("sum to {:.6g}; allowed 1 +- 0.001", sum));
    }
    std::string symbol = v.string("symbol");
    if (symbol == "-") symbol = p.name.substr(0, 1);
    for (char ch : symbol)
      if (!std::isalpha(static_cast<unsigned char>(ch)))
        throw v.error("symbol", "= \"" + symbol + "\" must be letters only");
    for (std::size_t k = 0; k < c.coal_symbols.size(); ++k)
      if (c.coal_symbols[k] == symbol)
        throw v.error("symbol", fmt::format("= \"{}\" is already the symbol of coal \"{}\"; give "
                                            "each coal its own symbol",
                                            symbol, c.coals[k].name));
    c.coal_symbols.push_back(symbol);
    c.coals.push_back(p);
    c.coal_places.push_back(v.place);
  }
  // [contact.*]
  {
    std::vector<std::string> names;
    for (const auto& coal : c.coals) names.push_back(coal.name);
    c.particle_particle = r.contact(root, "particle_particle", false, names);
    c.particle_wall = r.contact(root, "particle_wall", true, names);
  }
  for (const ContactSpec* spec : {&c.particle_particle, &c.particle_wall}) {
    if (spec->cohesion.law == "none") continue;
    for (std::size_t k = 0; k < c.coals.size(); ++k)
      if (!missing_measured[k].empty())
        throw InputError(
            c.coal_places[k], fmt::format("coal[{}].{}", k, missing_measured[k]),
            fmt::format("missing: the cohesion law \"{}\" of [contact.{}] needs it to derive the "
                        "cohesive force (Eq. 14-16); give it, or cohesion_force_n, or use "
                        "cohesion = {{ law = \"none\" }} in both contact sections",
                        spec->cohesion.law,
                        spec == &c.particle_particle ? "particle_particle" : "particle_wall"));
  }
  if (const toml::node* cn = root.get("contact")) {
    for (const auto& [k, node] : *cn->as_table()) {
      const std::string key(k.str());
      if (key != "particle_particle" && key != "particle_wall") {
        const std::string hint = did_you_mean(key, {"particle_particle", "particle_wall"});
        throw InputError(
            r.place(node), "contact." + key,
            "unknown section" + (hint.empty() ? std::string() : "; did you mean '" + hint + "'?"));
      }
    }
  }
  // [[wall]]
  {
    const auto ws = r.tables(root, "wall");
    std::vector<std::string> types;
    for (const auto& w : wall_types()) types.emplace_back(w.name);
    for (std::size_t i = 0; i < ws.size(); ++i) {
      const std::string sec = fmt::format("wall[{}]", i);
      const toml::node* t = ws[i]->get("type");
      if (!t || !t->is_string())
        throw InputError(
            r.place(*ws[i]), sec + ".type",
            fmt::format("missing or not a string; choose one of: {}", fmt::join(types, ", ")));
      const std::string type = t->value<std::string>().value();
      const WallEntry* e = find_wall_type(type);
      if (!e) {
        const std::string hint = did_you_mean(type, types);
        throw InputError(r.place(*t), sec + ".type",
                         fmt::format("= \"{}\" is not a wall type; choose one of: {}{}", type,
                                     fmt::join(types, ", "),
                                     hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      WallSpec spec{type, r.read(*ws[i], e->fields(), sec, {"type"})};
      e->make(spec.values);  // validates geometry now, so errors come before any output
      c.walls.push_back(std::move(spec));
    }
  }
  // [[particle]], [[lattice]]
  {
    const auto ps = r.tables(root, "particle");
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::string sec = fmt::format("particle[{}]", i);
      ParticleSpec p;
      const ParamValues v = r.read_into(p, *ps[i], particle_fields(), sec);
      p.coal = coal_index(c, v, "coal");
      p.place = v.places.at("position");
      p.key = sec;
      c.particles.push_back(p);
    }
    const auto ls = r.tables(root, "lattice");
    for (std::size_t i = 0; i < ls.size(); ++i) {
      const std::string sec = fmt::format("lattice[{}]", i);
      LatticeSpec l;
      const ParamValues v = r.read_into(l, *ls[i], lattice_fields(), sec);
      l.coal = coal_index(c, v, "coal");
      const Vec3 n = v.vector("count");
      for (double x : {n.x, n.y, n.z})
        if (x < 1 || x > 1e4 || x != std::floor(x))
          throw v.error(
              "count",
              fmt::format("components must be integers in [1, 10000], got ({:g}, {:g}, {:g})", n.x,
                          n.y, n.z));
      l.nx = int(n.x), l.ny = int(n.y), l.nz = int(n.z);
      if (double(l.nx) * l.ny * l.nz > 2e7) throw v.error("count", "more than 2e7 particles");
      l.place = v.place;
      l.key = sec;
      c.lattices.push_back(l);
    }
  }
  // [silo], [fill], [discharge]
  if (root.get("silo")) {
    c.silo.present = true;
    auto& g = c.silo.geometry;
    const ParamValues v = r.read_into(g, single("silo"), silo_fields(), "silo");
    double d_min = 1e300;
    for (const auto& coal : c.coals) {
      d_min = std::min(d_min, coal.diameter);
      for (const auto& sc : coal.size_classes) d_min = std::min(d_min, sc.diameter);
    }
    d_min *= c.cg.k;
    if (g.valve_gap >= 0.5 * d_min)
      throw v.error("valve_gap_mm",
                    fmt::format("= {:g} must be below half the smallest CG diameter ({:g} mm): "
                                "a wider gap between plate and rim is open at the sides",
                                g.valve_gap * 1e3, 0.5 * d_min * 1e3));
    if (g.cylinder_diameter <= g.outlet_diameter)
      throw v.error("cylinder_diameter_mm",
                    fmt::format("= {:g} must be larger than outlet_diameter_mm = {:g}",
                                g.cylinder_diameter * 1e3, g.outlet_diameter * 1e3));
    if (!c.particles.empty() || !c.lattices.empty())
      throw v.error("", "a silo case fills itself: remove the [[particle]] and [[lattice]] tables");
    const toml::node* fn = root.get("fill");
    if (!fn)
      throw InputError({file, 1, 1}, "fill", "missing: a silo case needs [fill] with a scenario");
    const ParamValues f = r.read_into(c.fill, single("fill"), fill_fields(), "fill");
    c.fill.scenario_place = f.places.count("scenario") ? f.places.at("scenario") : f.place;
    if (c.fill.fill_height > g.total_height())
      throw f.error("fill_height_mm",
                    fmt::format("= {:g} is above the silo ({:g} mm)", c.fill.fill_height * 1e3,
                                g.total_height() * 1e3));
    std::vector<Layer> layers;
    try {
      layers = parse_scenario(c.fill.scenario);
    } catch (const std::invalid_argument& e) {
      throw f.error("scenario", e.what());
    }
    int used = 0;
    for (const auto& l : layers) {
      used += l.segments;
      if (std::find(c.coal_symbols.begin(), c.coal_symbols.end(), l.symbol) == c.coal_symbols.end())
        throw f.error("scenario",
                      fmt::format("= \"{}\": no coal has the symbol \"{}\" (known: {})",
                                  c.fill.scenario, l.symbol, fmt::join(c.coal_symbols, ", ")));
    }
    if (used > c.fill.segments)
      throw f.error("scenario", fmt::format("= \"{}\" needs {} segments but fill.segments = {}",
                                            c.fill.scenario, used, c.fill.segments));
    if (c.fill.mode == FillMode::Mass)
      for (std::size_t k = 0; k < c.coals.size(); ++k)
        if (c.coals[k].bulk_density <= 0)
          throw InputError(c.coal_places[k], fmt::format("coal[{}].bulk_density_kg_m3", k),
                           "missing: filling by mass needs the measured bulk density");
    const ParamValues d =
        r.read_into(c.discharge, single("discharge"), discharge_fields(), "discharge");
    if (c.discharge.max_time / c.discharge.bin > 1e7)
      throw d.error("bin", fmt::format("= {:g} s gives more than 1e7 bins over max_time = {:g} s",
                                       c.discharge.bin, c.discharge.max_time));
    ProbeSpec& ps = c.probes;
    const ParamValues pr = r.read_into(ps, single("probes"), probe_fields(), "probes");
    std::sort(ps.slab_times.begin(), ps.slab_times.end());
    if (ps.profile_to <= ps.profile_from)
      throw pr.error("profile_to", fmt::format("= {:g} s must be after profile_from = {:g} s",
                                               ps.profile_to, ps.profile_from));
  } else {
    for (const char* s : {"fill", "discharge", "probes"})
      if (const toml::node* n = root.get(s))
        throw InputError(r.place(*n), s, "only a silo case (with [silo]) has this section");
  }

  // [output]
  {
    const ParamValues v = r.read_into(c.output, single("output"), output_fields(), "output");
    if (c.output.vtk_interval > 0 && !c.silo.present)
      throw v.error("vtk_interval", "ParaView frames are written by silo runs only");
    if (const std::string& m = v.string("measured"); !m.empty()) {
      if (!c.silo.present) throw v.error("measured", "measured outlet data needs a silo case");
      const std::filesystem::path base = base_dir.empty()
                                             ? std::filesystem::path(file).parent_path()
                                             : std::filesystem::path(base_dir);
      const std::filesystem::path mp =
          std::filesystem::path(m).is_absolute() ? std::filesystem::path(m) : base / m;
      c.output.measured = mp.string();
      c.output.measured_place = v.places.at("measured");
      c.measured = load_measured_csv(c.output.measured, c.output.measured_place);
    }
  }
  return c;
}

Case parse(const std::string& text, const std::string& name,
           const std::vector<std::string>& overrides = {}, const std::string& base_dir = {}) {
  try {
    toml::table root = toml::parse(text, name);
    for (const auto& o : overrides) apply_override(root, o);
    return build(root, name, base_dir);
  } catch (const toml::parse_error& e) {
    const auto& s = e.source();
    throw InputError({name, int(s.begin.line), int(s.begin.column)}, "",
                     std::string("TOML syntax error: ") + std::string(e.description()));
  } catch (const std::invalid_argument& e) {
    throw InputError({name, 0, 0}, "", e.what());
  }
}

}  // namespace

// Applies "a.b.c=value" (value in TOML syntax; a bare word is taken as a string).
void apply_override(toml::table& root, const std::string& item) {
  const auto eq = item.find('=');
  const SourcePlace here{"--set " + item, 0, 0};
  if (eq == std::string::npos || eq == 0)
    throw InputError(here, "", "expected key=value, e.g. --set coarse_graining.k=4");
  const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
  toml::table snippet;
  try {
    snippet = toml::parse("v = " + value, "--set " + item);
  } catch (const toml::parse_error&) {
    snippet = toml::parse("v = \"" + value + "\"", "--set " + item);
  }
  toml::table* t = &root;
  std::size_t start = 0;
  for (;;) {
    const auto dot = key.find('.', start);
    std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    long index = -1;  // coal[1]
    if (const auto br = part.find('['); br != std::string::npos && part.back() == ']') {
      const std::string digits = part.substr(br + 1, part.size() - br - 2);
      if (digits.empty() || digits.size() > 6 ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        throw InputError(here, key, "'" + part + "': the index must be a number, e.g. coal[1]");
      index = std::stol(digits);
      part = part.substr(0, br);
    }
    if (part.empty()) throw InputError(here, key, "empty key component");
    if (dot == std::string::npos) {
      t->insert_or_assign(part, std::move(*snippet.get("v")));
      return;
    }
    toml::node* next = t->get(part);
    if (index >= 0) {
      toml::array* a = next ? next->as_array() : nullptr;
      if (!a || index >= long(a->size()) || !(*a)[std::size_t(index)].is_table())
        throw InputError(here, key,
                         "no table " + part + "[" + std::to_string(index) + "] in the case");
      t = (*a)[std::size_t(index)].as_table();
    } else {
      if (!next) next = &t->insert_or_assign(part, toml::table{}).first->second;
      if (!next->is_table()) throw InputError(here, key, "'" + part + "' is not a table");
      t = next->as_table();
    }
    start = dot + 1;
  }
}

Case load_case_file(const std::string& path, const std::vector<std::string>& overrides,
                    const std::string& base_dir) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "", "cannot open the case file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path, overrides, base_dir);
}

Case load_case_text(const std::string& text, const std::string& name) {
  return parse(text, name);
}

}  // namespace silodem::config
