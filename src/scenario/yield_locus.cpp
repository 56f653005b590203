// SPDX-License-Identifier: MIT
#include "scenario/yield_locus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace silodem {

FailurePick pick_failure(const std::vector<StressPoint>& rows, FailureCriterion criterion) {
  FailurePick pick;
  bool found = false;
  double best = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t i0 = i > 0 ? i - 1 : 0, i1 = std::min(rows.size() - 1, i + 1);
    StressPoint m;
    for (std::size_t j = i0; j <= i1; ++j) m.sigma += rows[j].sigma, m.tau += rows[j].tau;
    m.sigma /= double(i1 - i0 + 1), m.tau /= double(i1 - i0 + 1);
    if (criterion == FailureCriterion::PeakRatio && !(m.sigma > 0)) continue;
    const double key = criterion == FailureCriterion::PeakRatio ? m.tau / m.sigma : m.tau;
    if (!std::isfinite(key)) continue;
    if (!found || key > best) found = true, best = key, pick.point = m, pick.row = i;
  }
  if (!found)
    throw std::invalid_argument(criterion == FailureCriterion::PeakRatio
                                    ? "no window with a finite tau / sigma and sigma > 0"
                                    : "no window with a finite shear stress");
  return pick;
}

const char* failure_criterion_name(FailureCriterion c) {
  return c == FailureCriterion::PeakTau ? "peak-tau" : "peak-ratio";
}

YieldLocus fit_yield_locus(const std::vector<StressPoint>& pts, const StressPoint& pre) {
  const double n = double(pts.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& p : pts)
    sx += p.sigma, sy += p.tau, sxx += p.sigma * p.sigma, sxy += p.sigma * p.tau;
  const double den = n * sxx - sx * sx;
  if (pts.size() < 2 || !(den > 1e-12 * sxx * n))
    throw std::invalid_argument("the yield locus needs two failure points at different stresses");
  const double slope = (n * sxy - sx * sy) / den;
  YieldLocus y;
  y.cohesion = (sy - slope * sx) / n;
  y.friction_angle = std::atan(slope);
  double r2 = 0;
  for (const auto& p : pts) r2 += std::pow(p.tau - y.cohesion - slope * p.sigma, 2);
  y.rms_residual = std::sqrt(r2 / n);
  if (pts.size() > 2) {
    const double sxx_c = sxx - sx * sx / n, s2 = r2 / (n - 2), mean = sx / n;
    const double se_slope = std::sqrt(s2 / sxx_c);
    y.cohesion_stderr = std::sqrt(s2 * (1 / n + mean * mean / sxx_c));
    y.friction_angle_stderr = se_slope / (1 + slope * slope);
  } else {
    y.cohesion_stderr = y.friction_angle_stderr = std::numeric_limits<double>::quiet_NaN();
  }

  const double s = std::sin(y.friction_angle), c = std::cos(y.friction_angle);
  // A circle of centre m on the sigma axis is tangent to tau = C + sigma tan(phi) when its radius
  // is the distance from (m, 0) to the line: R = m sin(phi) + C cos(phi).
  if (y.cohesion > 0) {
    // Through the origin: R = m, so m = C cos(phi) / (1 - sin(phi)).
    const double m = y.cohesion * c / (1 - s);
    y.unconfined = {m, m};
    y.unconfined_yield = 2 * m;
  }
  // Through the pre-shear point: (sigma_p - m)^2 + tau_p^2 = (m s + C c)^2, the larger root.
  const double k = y.cohesion * c;
  const double a = 1 - s * s, b = -2 * (pre.sigma + s * k),
               q = pre.sigma * pre.sigma + pre.tau * pre.tau - k * k;
  const double disc = b * b - 4 * a * q;
  if (disc >= 0) {
    const double m = (-b + std::sqrt(disc)) / (2 * a);
    y.consolidation = {m, m * s + k};
  } else {
    y.consolidation_tangent = false;
    y.consolidation = {pre.sigma, std::abs(pre.tau)};
  }
  y.major_consolidation = y.consolidation.centre + y.consolidation.radius;
  y.flow_function = y.unconfined_yield > 0 ? y.major_consolidation / y.unconfined_yield
                                           : std::numeric_limits<double>::infinity();
  return y;
}

}  // namespace silodem
