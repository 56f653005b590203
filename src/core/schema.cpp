// SPDX-License-Identifier: MIT
#include "core/schema.hpp"

#include <fmt/format.h>
#include <cmath>

namespace silodem {

Field Field::number(std::string key, std::string doc, std::string unit, double to_si) {
  Field f;
  f.key = std::move(key), f.doc = std::move(doc), f.unit = std::move(unit), f.to_si = to_si;
  f.kind = FieldKind::Number;
  return f;
}
Field Field::integer(std::string key, std::string doc) {
  Field f = number(std::move(key), std::move(doc));
  f.kind = FieldKind::Integer;
  return f;
}
Field Field::flag(std::string key, std::string doc, bool def) {
  Field f = number(std::move(key), std::move(doc));
  f.kind = FieldKind::Bool;
  f.default_number = def ? 1.0 : 0.0;
  return f;
}
Field Field::text(std::string key, std::string doc, std::vector<std::string> choices,
                  std::string def) {
  Field f = number(std::move(key), std::move(doc));
  f.kind = FieldKind::String;
  f.choices = std::move(choices);
  f.default_string = std::move(def);
  f.required = f.default_string.empty();
  return f;
}
Field Field::integer_list(std::string key, std::string doc) {
  Field f = number(std::move(key), std::move(doc));
  f.kind = FieldKind::IntegerList;
  return f;
}
Field Field::number_list(std::string key, std::string doc, std::string unit, double to_si) {
  Field f = number(std::move(key), std::move(doc), std::move(unit), to_si);
  f.kind = FieldKind::NumberList;
  return f;
}
Field Field::vec3(std::string key, std::string doc, std::string unit, double to_si) {
  Field f = number(std::move(key), std::move(doc), std::move(unit), to_si);
  f.kind = FieldKind::Vec3;
  return f;
}

static std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{:g}", v);
}

std::string Field::range_text() const {
  return fmt::format("{}{}, {}{}", min_exclusive ? "(" : "[", num(min), num(max),
                     max_exclusive ? ")" : "]");
}

bool Field::in_range(double v) const {
  if (!std::isfinite(v)) return false;
  if (min_exclusive ? !(v > min) : !(v >= min)) return false;
  if (max_exclusive ? !(v < max) : !(v <= max)) return false;
  return true;
}

double ParamValues::number(const std::string& key) const {
  auto it = numbers.find(key);
  if (it == numbers.end()) throw error(key, "internal: number not declared in the schema");
  return it->second;
}
const std::string& ParamValues::string(const std::string& key) const {
  auto it = strings.find(key);
  if (it == strings.end()) throw error(key, "internal: string not declared in the schema");
  return it->second;
}
Vec3 ParamValues::vector(const std::string& key) const {
  auto it = vectors.find(key);
  if (it == vectors.end()) throw error(key, "internal: vector not declared in the schema");
  return it->second;
}
bool ParamValues::has(const std::string& key) const {
  return numbers.count(key) || strings.count(key) || vectors.count(key) || lists.count(key);
}
bool ParamValues::was_given(const std::string& key) const {
  auto it = given.find(key);
  return it != given.end() && it->second;
}
InputError ParamValues::error(const std::string& key, const std::string& message) const {
  auto it = places.find(key);
  const SourcePlace& p = it != places.end() ? it->second : place;
  return InputError(p, section.empty() ? key : section + "." + key, message);
}

}  // namespace silodem
