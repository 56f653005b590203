// SPDX-License-Identifier: MIT
// Seeded random numbers that give the same sequence on every platform and compiler
// (std::uniform_real_distribution is implementation-defined, so we map the raw 64 bits ourselves).
#pragma once
#include <cstdint>

namespace silodem {

// SplitMix64 (Steele, Lea & Flood 2014): small state, full period 2^64, good enough for placing
// particles and sampling sizes.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next_u64() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  std::uint64_t state() const { return state_; }
  void set_state(std::uint64_t s) { state_ = s; }

 private:
  std::uint64_t state_;
};

}  // namespace silodem
