// SPDX-License-Identifier: MIT
// Cohesive force on the particles in the hopper (paper Fig. 15): per particle, the sum of the
// magnitudes of the cohesive forces of its contacts (particles and walls); the mean over the
// particles in the hopper and the largest.
#include <algorithm>

#include "probes/probes.hpp"

namespace silodem {
namespace {

class CohesionForceProbe final : public Probe {
 public:
  std::string name() const override { return "cohesion_force"; }
  std::vector<std::string> columns() const override {
    return {"t_s", "particles", "mean_cohesive_force_n", "max_cohesive_force_n"};
  }
  void sample(ProbeView& view, std::vector<ProbeRow>& rows) override {
    const ParticleStore& p = view.particles();
    const ContactTally& t = view.tally();
    long n = 0;
    double sum = 0.0, mx = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!in_hopper(p, i)) continue;
      ++n;
      sum += t.cohesion_sum[i];
      mx = std::max(mx, t.cohesion_sum[i]);
    }
    rows.push_back({view.t(), double(n), n > 0 ? sum / double(n) : 0.0, mx});
  }
};

}  // namespace

std::unique_ptr<Probe> make_cohesion_force_probe(const ProbeSpec&, const ProbeSite&) {
  return std::make_unique<CohesionForceProbe>();
}

}  // namespace silodem
