// SPDX-License-Identifier: MIT
// Self-describing input fields (key, type, unit, default, range, choices, help), declared once.
// io/config validates TOML against these lists and generates docs/config.md from them; laws in
// model/ read already-validated values through ParamValues, so they never see TOML.
#pragma once
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/vec3.hpp"

namespace silodem {

enum class FieldKind { Number, Integer, Bool, String, Vec3, IntegerList, NumberList };

struct Field {
  std::string key;
  FieldKind kind = FieldKind::Number;
  std::string doc;
  std::string unit;    // unit the case file uses ("mm", "kPa", ...); empty = SI or dimensionless
  double to_si = 1.0;  // factor from the case-file unit to SI
  bool required = false;
  std::optional<double> default_number;  // Number, Integer, Bool (0/1)
  std::string default_string;            // String
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  bool max_exclusive = false;
  std::vector<std::string> choices;  // String: allowed values

  // Builder helpers keep the field tables short and readable.
  static Field number(std::string key, std::string doc, std::string unit = {}, double to_si = 1.0);
  static Field integer(std::string key, std::string doc);
  static Field flag(std::string key, std::string doc, bool def);
  static Field text(std::string key, std::string doc, std::vector<std::string> choices,
                    std::string def = {});
  static Field vec3(std::string key, std::string doc, std::string unit = {}, double to_si = 1.0);
  static Field integer_list(std::string key, std::string doc);
  // Numbers in case-file units, each checked against the range.
  static Field number_list(std::string key, std::string doc, std::string unit = {},
                           double to_si = 1.0);
  Field& with_default(double v) {
    default_number = v;
    return *this;
  }
  Field& needed() {
    required = true;
    return *this;
  }
  Field& optional() {
    required = false;
    return *this;
  }
  Field& above(double v) {
    min = v, min_exclusive = true;
    return *this;
  }
  Field& at_least(double v) {
    min = v, min_exclusive = false;
    return *this;
  }
  Field& below(double v) {
    max = v, max_exclusive = true;
    return *this;
  }
  Field& at_most(double v) {
    max = v, max_exclusive = false;
    return *this;
  }
  // "(0, 1]", "[1, inf)" ... in case-file units.
  std::string range_text() const;
  bool in_range(double v_case_units) const;
};

// Validated values of one section (already in SI), with where each came from.
struct ParamValues {
  std::string section;  // e.g. "contact.particle_particle.tangential"
  SourcePlace place;    // where the section starts
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> strings;
  std::map<std::string, Vec3> vectors;
  std::map<std::string, std::vector<double>> lists;
  std::map<std::string, SourcePlace> places;  // per key, for error messages
  std::map<std::string, bool> given;          // true if the key was written in the file

  double number(const std::string& key) const;
  bool flag(const std::string& key) const { return number(key) != 0.0; }
  const std::string& string(const std::string& key) const;
  Vec3 vector(const std::string& key) const;
  bool has(const std::string& key) const;
  bool was_given(const std::string& key) const;
  // An input error located at `key` (or at the section when the key is absent).
  InputError error(const std::string& key, const std::string& message) const;
};

}  // namespace silodem
