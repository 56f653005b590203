// SPDX-License-Identifier: MIT
// Error types. Input errors carry the place in the case file (file:line:column) and the key, so
// that the command line can print one line that names key, value, allowed range and location.
#pragma once
#include <stdexcept>
#include <string>

namespace silodem {

struct SourcePlace {
  std::string file;
  int line = 0;    // 1-based; 0 when unknown
  int column = 0;  // 1-based; 0 when unknown
  std::string str() const;
};

// Bad input: a case file, a command-line value, a physically impossible combination.
class InputError : public std::runtime_error {
 public:
  InputError(SourcePlace place, std::string key, std::string message);
  const SourcePlace& place() const { return place_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  SourcePlace place_;
  std::string key_;
  std::string message_;
};

// A running simulation that went wrong (NaN, escaping particle, ...).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace silodem
