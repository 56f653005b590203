// SPDX-License-Identifier: MIT
// Self-describing input fields (key, type, unit, default, range, choices, help), declared once.
// io/config validates TOML against these lists and generates docs/config.md from them; laws in
// model/ read already-validated values through ParamValues, so they never see TOML.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
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
  bool optional_text = false;        // String without a default that may be left out
  bool no_default = false;           // bind(): the member's initial value means "not given"

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
  Field& without_default() {
    no_default = true;
    return *this;
  }
  Field& needed() {
    required = true;
    return *this;
  }
  Field& optional() {
    required = false;
    optional_text = true;
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

// A field bound to the member of a spec struct S that holds its value: the one place that says
// where a key goes. The member's value in a default-constructed S is the default (the docs show it
// in the case file's unit); a key that is not given leaves the member at it. A default outside the
// field's range, or one marked without_default(), is a "not given" marker (the doc text says what
// it means) and is shown as "-".
// Fields that need more than a copy (an enum, an optional, a value read with others) take a
// setter; a field with neither member nor setter is read by the loader's cross-field checks.
template <class S>
struct Bound {
  using Member = std::variant<std::monostate, double S::*, int S::*, long S::*, std::uint64_t S::*,
                              bool S::*, std::string S::*, Vec3 S::*, std::vector<double> S::*>;
  Field field;
  Member member;
  std::function<void(S&, const ParamValues&)> set;  // called only when the key was given
};

template <class S, class T>
Bound<S> bind(Field f, T S::*member) {
  const S defaults{};
  const T& d = defaults.*member;
  if constexpr (std::is_same_v<T, std::string>) {
    f.default_string = d;
    f.required = d.empty() && f.kind == FieldKind::String && !f.optional_text;
  } else if constexpr (std::is_arithmetic_v<T>) {
    const double v = double(d) / f.to_si;
    if (!f.no_default && (f.kind == FieldKind::Bool || f.in_range(v))) f.default_number = v;
  }
  return {std::move(f), member, {}};
}

// A field whose value a setter stores (called only when the key is given; the default is the
// field's own, or the member's in S{} that the setter writes).
template <class S>
Bound<S> bind(Field f, std::function<void(S&, const ParamValues&)> set) {
  return {std::move(f), std::monostate{}, std::move(set)};
}

// A field the loader reads itself (its use needs other sections).
template <class S>
Bound<S> unbound(Field f) {
  return {std::move(f), std::monostate{}, {}};
}

template <class S>
std::vector<Field> fields_of(const std::vector<Bound<S>>& bound) {
  std::vector<Field> out;
  out.reserve(bound.size());
  for (const auto& b : bound) out.push_back(b.field);
  return out;
}

// Copies every given key of `v` into its member of `s` (values already in SI and range-checked).
template <class S>
void assign(S& s, const std::vector<Bound<S>>& bound, const ParamValues& v) {
  for (const auto& b : bound) {
    const std::string& key = b.field.key;
    if (!v.was_given(key)) continue;
    if (b.set) {
      b.set(s, v);
      continue;
    }
    std::visit(
        [&](auto m) {
          using M = decltype(m);
          if constexpr (std::is_same_v<M, std::monostate>) {
            return;
          } else {
            using T = std::remove_reference_t<decltype(s.*m)>;
            if constexpr (std::is_same_v<T, std::string>)
              s.*m = v.string(key);
            else if constexpr (std::is_same_v<T, Vec3>)
              s.*m = v.vector(key);
            else if constexpr (std::is_same_v<T, std::vector<double>>)
              s.*m = v.lists.at(key);
            else if constexpr (std::is_same_v<T, bool>)
              s.*m = v.flag(key);
            else
              s.*m = T(v.number(key));
          }
        },
        b.member);
  }
}

}  // namespace silodem
