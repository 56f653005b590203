// SPDX-License-Identifier: MIT
// Vertical velocity across the width (paper Fig. 12): at each chosen height h above the outlet,
// particles with |z - h| <= bin/2 in the slab |y| <= thickness/2 are binned by x (bins of width
// `bin` from the cylinder wall to the cylinder wall) and their v_z averaged over all samples in
// the time window (each particle in each sample counts once). Rows come at the end of the run.
#include <cmath>
#include <stdexcept>

#include "probes/probes.hpp"

namespace silodem {
namespace {

class VelocityProfileProbe final : public Probe {
 public:
  VelocityProfileProbe(const ProbeSpec& s, double half_width)
      : heights_(s.profile_heights),
        bin_(s.profile_bin),
        half_slab_(0.5 * s.slab_thickness),
        from_(s.profile_from),
        to_(s.profile_to),
        x0_(-half_width),
        nbins_(std::max(1, int(std::ceil(2.0 * half_width / s.profile_bin)))),
        sum_(heights_.size() * std::size_t(nbins_), 0.0),
        sum2_(sum_.size(), 0.0),
        count_(sum_.size(), 0) {}
  std::string name() const override { return "velocity_profile"; }
  std::vector<std::string> columns() const override {
    return {"height_m", "x_m", "vz_mean_m_s", "vz_std_m_s", "samples", "t_from_s", "t_to_s"};
  }
  void sample(ProbeView& view, std::vector<ProbeRow>&) override {
    if (view.t() < from_ - 1e-12 || view.t() > to_ + 1e-12) return;
    first_ = std::min(first_, view.t());
    last_ = std::max(last_, view.t());
    const ParticleStore& p = view.particles();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (std::fabs(p.x[i].y) > half_slab_) continue;
      const int b = int(std::floor((p.x[i].x - x0_) / bin_));
      if (b < 0 || b >= nbins_) continue;
      for (std::size_t h = 0; h < heights_.size(); ++h) {
        if (std::fabs(p.x[i].z - heights_[h]) > 0.5 * bin_) continue;
        const std::size_t k = h * std::size_t(nbins_) + std::size_t(b);
        sum_[k] += p.v[i].z;
        sum2_[k] += p.v[i].z * p.v[i].z;
        ++count_[k];
      }
    }
  }
  void finish(std::vector<ProbeRow>& rows) override {
    const double nan = std::nan("");
    const bool any = first_ <= last_;
    for (std::size_t h = 0; h < heights_.size(); ++h)
      for (int b = 0; b < nbins_; ++b) {
        const std::size_t k = h * std::size_t(nbins_) + std::size_t(b);
        const double n = double(count_[k]);
        const double mean = n > 0 ? sum_[k] / n : nan;
        const double var = n > 0 ? std::max(0.0, sum2_[k] / n - mean * mean) : nan;
        rows.push_back({heights_[h], x0_ + (b + 0.5) * bin_, mean, std::sqrt(var), n,
                        any ? first_ : nan, any ? last_ : nan});
      }
  }
  void save(ByteWriter& w) const override {
    w.put(sum_), w.put(sum2_), w.put(count_), w.put(first_), w.put(last_);
  }
  void load(ByteReader& r) override {
    r.get(sum_), r.get(sum2_), r.get(count_), r.get(first_), r.get(last_);
    if (sum_.size() != count_.size() || sum2_.size() != count_.size())
      throw std::runtime_error("checkpoint: velocity profile bins differ from the case");
  }

 private:
  std::vector<double> heights_;
  double bin_, half_slab_, from_, to_, x0_;
  int nbins_;
  std::vector<double> sum_, sum2_;
  std::vector<long> count_;
  double first_ = 1e300, last_ = -1e300;
};

}  // namespace

std::unique_ptr<Probe> make_velocity_profile_probe(const ProbeSpec& spec, const ProbeSite& site) {
  return std::make_unique<VelocityProfileProbe>(spec, site.silo_radius);
}

}  // namespace silodem
