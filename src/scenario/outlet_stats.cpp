// SPDX-License-Identifier: MIT
#include "scenario/outlet_stats.hpp"

#include <cmath>
#include <limits>

namespace silodem {

double mixture_calorific(const std::vector<double>& m, const std::vector<double>& q) {
  double total = 0.0, heat = 0.0;
  for (std::size_t c = 0; c < m.size(); ++c) total += m[c], heat += m[c] * q[c];
  return total > 0.0 ? heat / total : std::numeric_limits<double>::quiet_NaN();
}

std::vector<OutletBin> outlet_bins(const std::vector<OutletRecord>& out, double bin, double t_end,
                                   const std::vector<double>& q) {
  const std::size_t ncoal = q.size();
  const std::size_t nbin = std::max<std::size_t>(1, std::size_t(std::ceil(t_end / bin - 1e-9)));
  std::vector<std::vector<double>> per(nbin, std::vector<double>(ncoal, 0.0));
  for (const auto& rec : out) {
    const std::size_t b = std::min(nbin - 1, std::size_t(rec.t / bin));
    per[b][std::size_t(rec.coal)] += rec.mass;
  }
  std::vector<OutletBin> bins(nbin);
  double cum = 0.0;
  for (std::size_t b = 0; b < nbin; ++b) {
    OutletBin& o = bins[b];
    o.t_start = double(b) * bin;
    o.t_end = std::min(double(b + 1) * bin, std::max(t_end, o.t_start + 1e-12));
    for (double m : per[b]) o.mass += m;
    o.rate = o.mass / (o.t_end - o.t_start);
    cum += o.mass;
    o.cumulative = cum;
    o.fraction.resize(ncoal);
    for (std::size_t c = 0; c < ncoal; ++c)
      o.fraction[c] = o.mass > 0 ? per[b][c] / o.mass : std::numeric_limits<double>::quiet_NaN();
    o.calorific = mixture_calorific(per[b], q);
  }
  return bins;
}

}  // namespace silodem
