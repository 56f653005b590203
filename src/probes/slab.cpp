// SPDX-License-Identifier: MIT
// Flow pattern (paper Figs. 10-11): at each chosen time, every particle whose centre lies in the
// vertical slab |y| <= half width through the silo axis, with its coal and velocity. A snapshot is
// taken at the first sample at or after its time; the row records the time it was taken.
#include <cmath>

#include "probes/probes.hpp"

namespace silodem {
namespace {

class SlabProbe final : public Probe {
 public:
  explicit SlabProbe(const ProbeSpec& s) : times_(s.slab_times), half_(0.5 * s.slab_thickness) {}
  std::string name() const override { return "slab"; }
  std::vector<std::string> columns() const override {
    return {"t_s", "id", "coal", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s", "radius_m"};
  }
  void sample(ProbeView& view, std::vector<ProbeRow>& rows) override {
    bool due = false;
    while (next_ < times_.size() && view.t() >= times_[next_] - 1e-12) due = true, ++next_;
    if (!due) return;
    const ParticleStore& p = view.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (std::fabs(p.x[i].y) > half_) continue;
      rows.push_back({view.t(), double(p.id[i]), double(p.material[i]), p.x[i].x, p.x[i].y,
                      p.x[i].z, p.v[i].x, p.v[i].y, p.v[i].z, p.radius[i]});
    }
  }
  void save(ByteWriter& w) const override { w.put(std::uint64_t(next_)); }
  void load(ByteReader& r) override { next_ = std::size_t(r.get<std::uint64_t>()); }

 private:
  std::vector<double> times_;  // sorted
  double half_;
  std::size_t next_ = 0;
};

}  // namespace

std::unique_ptr<Probe> make_slab_probe(const ProbeSpec& spec, const ProbeSite&) {
  return std::make_unique<SlabProbe>(spec);
}

}  // namespace silodem
