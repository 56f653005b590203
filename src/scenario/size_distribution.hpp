// SPDX-License-Identifier: MIT
// Particle sizes of a coal: one diameter, or a sieve table (class diameters and mass fractions)
// sampled by number with a seeded generator; the result is multiplied by k.
#pragma once
#include "core/random.hpp"
#include "model/coarse_graining.hpp"
#include "model/material.hpp"

namespace silodem {

class SizeSampler {
 public:
  SizeSampler(const CoalProperties& coal, const CoarseGraining& cg);
  double sample(Random& rng) const;  // coarse-grained diameter (m)
  double max_diameter() const { return d_max_; }
  double min_diameter() const { return d_min_; }

 private:
  std::vector<double> d_;    // CG class diameters
  std::vector<double> cdf_;  // cumulative number fractions
  double d_max_ = 0.0, d_min_ = 0.0;
};

}  // namespace silodem
