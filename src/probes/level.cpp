// SPDX-License-Identifier: MIT
// Material level on the centre line (paper Fig. 6): the highest particle top (z + r) among the
// particles whose centres lie within `level_radius` of the axis; empty when there is none.
#include <cmath>

#include "probes/probes.hpp"

namespace silodem {
namespace {

class LevelProbe final : public Probe {
 public:
  explicit LevelProbe(double radius) : r2_(radius * radius) {}
  std::string name() const override { return "level"; }
  std::vector<std::string> columns() const override { return {"t_s", "level_m"}; }
  void sample(ProbeView& view, std::vector<ProbeRow>& rows) override {
    const ParticleStore& p = view.particles();
    double top = -1e300;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.x[i].x * p.x[i].x + p.x[i].y * p.x[i].y <= r2_ && in_hopper(p, i))
        top = std::max(top, p.x[i].z + p.radius[i]);
    rows.push_back({view.t(), top > -1e300 ? top : std::nan("")});
  }

 private:
  double r2_;
};

}  // namespace

std::unique_ptr<Probe> make_level_probe(const ProbeSpec& spec, const ProbeSite&) {
  return std::make_unique<LevelProbe>(spec.level_radius);
}

}  // namespace silodem
