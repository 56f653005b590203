// SPDX-License-Identifier: MIT
#include "scenario/outlet_stats.hpp"

#include <algorithm>
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

namespace silodem {

MeasuredErrors compare_with_measured(const std::vector<OutletBin>& bins, const MeasuredData& m) {
  MeasuredErrors e;
  double rate_sum = 0.0, cal_sum = 0.0;
  for (std::size_t k = 0; k < m.t.size(); ++k) {
    const double t = m.t[k];
    const OutletBin* hit = nullptr;
    for (const auto& b : bins)
      if (b.t_start <= t && t < b.t_end) hit = &b;
    if (!hit) continue;
    auto add = [](double sim, double meas, int& n, double& sum, double& mx) {
      if (!std::isfinite(sim) || !std::isfinite(meas) || meas == 0.0) return;
      const double r = std::fabs(sim - meas) / std::fabs(meas);
      ++n, sum += r, mx = std::max(mx, r);
    };
    add(hit->rate, m.rate[k], e.rate_points, rate_sum, e.rate_max);
    add(hit->calorific, m.calorific[k], e.calorific_points, cal_sum, e.calorific_max);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  e.rate_mean = e.rate_points ? rate_sum / e.rate_points : nan;
  e.calorific_mean = e.calorific_points ? cal_sum / e.calorific_points : nan;
  if (!e.rate_points) e.rate_max = nan;
  if (!e.calorific_points) e.calorific_max = nan;
  return e;
}

}  // namespace silodem
