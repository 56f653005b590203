// SPDX-License-Identifier: MIT
// Share of adhered particles (paper Fig. 14): a particle in the hopper is adhered when a particle
// partner pulls on it with a cohesive force above the threshold (0.001 N by default).
#include "probes/probes.hpp"

namespace silodem {
namespace {

class AdhesionProbe final : public Probe {
 public:
  explicit AdhesionProbe(double threshold) : threshold_(threshold) {}
  std::string name() const override { return "adhesion"; }
  std::vector<std::string> columns() const override {
    return {"t_s", "particles", "adhered", "adhered_share"};
  }
  void sample(ProbeView& view, std::vector<ProbeRow>& rows) override {
    const ParticleStore& p = view.particles();
    const ContactTally& t = view.tally();
    long n = 0, adhered = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!in_hopper(p, i)) continue;
      ++n;
      if (t.cohesion_max_pp[i] > threshold_) ++adhered;
    }
    rows.push_back(
        {view.t(), double(n), double(adhered), n > 0 ? double(adhered) / double(n) : 0.0});
  }

 private:
  double threshold_;
};

}  // namespace

std::unique_ptr<Probe> make_adhesion_probe(const ProbeSpec& spec, const ProbeSite&) {
  return std::make_unique<AdhesionProbe>(spec.adhesion_threshold);
}

}  // namespace silodem
