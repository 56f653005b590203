// SPDX-License-Identifier: MIT
#include "scenario/size_distribution.hpp"

#include <algorithm>

namespace silodem {

SizeSampler::SizeSampler(const CoalProperties& coal, const CoarseGraining& cg) {
  if (coal.size_classes.empty()) {
    d_ = {cg.diameter(coal.diameter)};
    cdf_ = {1.0};
  } else {
    // A mass fraction w of spheres of diameter d is a number fraction proportional to w / d^3.
    double total = 0.0;
    for (const auto& c : coal.size_classes) {
      d_.push_back(cg.diameter(c.diameter));
      total += c.mass_fraction / (c.diameter * c.diameter * c.diameter);
      cdf_.push_back(total);
    }
    for (double& x : cdf_) x /= total;
  }
  d_max_ = *std::max_element(d_.begin(), d_.end());
  d_min_ = *std::min_element(d_.begin(), d_.end());
}

double SizeSampler::sample(Random& rng) const {
  if (d_.size() == 1) return d_[0];
  const double u = rng.uniform();
  const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
  return d_[std::min<std::size_t>(std::size_t(it - cdf_.begin()), d_.size() - 1)];
}

}  // namespace silodem
