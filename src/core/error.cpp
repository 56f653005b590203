// SPDX-License-Identifier: MIT
#include "core/error.hpp"

#include <fmt/format.h>

namespace silodem {

std::string SourcePlace::str() const {
  const std::string name = file.empty() ? std::string("<input>") : file;
  if (line <= 0) return name;
  if (column <= 0) return fmt::format("{}:{}", name, line);
  return fmt::format("{}:{}:{}", name, line, column);
}

static std::string compose(const SourcePlace& p, const std::string& key, const std::string& msg) {
  if (key.empty()) return fmt::format("{}: {}", p.str(), msg);
  return fmt::format("{}: '{}' {}", p.str(), key, msg);
}

InputError::InputError(SourcePlace place, std::string key, std::string message)
    : std::runtime_error(compose(place, key, message)),
      place_(std::move(place)),
      key_(std::move(key)),
      message_(std::move(message)) {}

}  // namespace silodem
