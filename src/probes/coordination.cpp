// SPDX-License-Identifier: MIT
// Mean coordination number of the particles in the hopper: touching particle partners per
// particle (wall contacts not counted).
#include "probes/probes.hpp"

namespace silodem {
namespace {

class CoordinationProbe final : public Probe {
 public:
  std::string name() const override { return "coordination"; }
  std::vector<std::string> columns() const override {
    return {"t_s", "particles", "mean_coordination"};
  }
  void sample(ProbeView& view, std::vector<ProbeRow>& rows) override {
    const ParticleStore& p = view.particles();
    const ContactTally& t = view.tally();
    long n = 0, contacts = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!in_hopper(p, i)) continue;
      ++n;
      contacts += t.particle_contacts[i];
    }
    rows.push_back({view.t(), double(n), n > 0 ? double(contacts) / double(n) : 0.0});
  }
};

}  // namespace

std::unique_ptr<Probe> make_coordination_probe(const ProbeSpec&, const ProbeSite&) {
  return std::make_unique<CoordinationProbe>();
}

}  // namespace silodem
