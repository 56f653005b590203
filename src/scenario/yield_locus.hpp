// SPDX-License-Identifier: MIT
// The yield locus of a shear test and its Mohr circles (Schulze, Powders and Bulk Solids, 2nd ed.
// 2021, 3.1-3.3; ASTM D7891 for the FT-4's procedure): the linear fit tau = C + sigma tan(phi)
// through the failure points, the unconfined yield strength f_c (the Mohr circle through the
// origin tangent to the locus), the major consolidation stress sigma_1 (the circle through the
// pre-shear point tangent to the locus) and the flow function ffc = sigma_1 / f_c.
#pragma once
#include <cstddef>
#include <vector>

namespace silodem {

struct StressPoint {
  double sigma = 0.0, tau = 0.0;  // Pa
};

struct MohrCircle {
  double centre = 0.0, radius = 0.0;  // Pa
};

struct YieldLocus {
  double cohesion = 0.0;        // C, Pa (the intercept; may come out negative)
  double friction_angle = 0.0;  // phi, rad (from the slope)
  double rms_residual = 0.0;    // Pa, of the fit
  // Standard errors of C and phi from the scatter about the line (ordinary least squares with
  // n - 2 degrees of freedom: se(b) = s / sqrt(Sxx), se(C) = s sqrt(1/n + mean(sigma)^2 / Sxx),
  // s^2 = SSE / (n - 2); phi's by the delta method, se(phi) = se(b) / (1 + b^2)). NaN with two
  // points, which leave no degree of freedom. At 3-7 kPa the intercept is an extrapolation past
  // the tested stresses: se(C) is sqrt(1/5 + 5^2/10) = 1.64 times the scatter s of one point.
  double cohesion_stderr = 0.0;        // Pa
  double friction_angle_stderr = 0.0;  // rad
  MohrCircle unconfined;               // through the origin, tangent: f_c = 2 radius
  MohrCircle consolidation;       // through the pre-shear point, tangent: sigma_1 = centre + radius
  double unconfined_yield = 0.0;  // f_c, Pa (0 when C <= 0)
  double major_consolidation = 0.0;   // sigma_1, Pa
  double flow_function = 0.0;         // ffc = sigma_1 / f_c (infinity when f_c = 0)
  bool consolidation_tangent = true;  // false: the pre-shear point lies above the locus, so no
                                      // circle through it is tangent; then sigma_1 is the larger
                                      // principal stress of the pre-shear point's own circle
                                      // centred on the sigma axis with tau_pre as its radius
};

// Where a shear to failure failed (scenario/shear_cell.hpp's rows, one per strain step). The
// FT-4 holds the normal stress while it shears; the cell's servo holds its mean, but in a cell of
// about a thousand parcels the normal stress swings by tens of percent as force chains form and
// buckle, and the shear stress swings with it (tau / sigma much less). So the largest shear
// stress of a shear (PeakTau) picks the largest swing of sigma, more for stiffer contacts, whose
// swings are larger; the largest mobilised friction tau / sigma (PeakRatio, the default) picks
// the material's peak at the normal stress it had there. Both use the three-row moving means of
// tau and sigma and give that window's mean (sigma, tau) as the failure point.
enum class FailureCriterion { PeakRatio, PeakTau };

struct FailurePick {
  StressPoint point;    // the window's mean sigma and tau (Pa)
  std::size_t row = 0;  // the window's centre row
};

// rows: the shear's (sigma, tau). Windows with a non-finite key, and for PeakRatio those with
// mean sigma <= 0, are never picked; throws std::invalid_argument if no window is left.
FailurePick pick_failure(const std::vector<StressPoint>& rows, FailureCriterion criterion);
const char* failure_criterion_name(FailureCriterion c);  // peak-ratio | peak-tau

// Least squares over at least two points with distinct sigma (throws std::invalid_argument).
YieldLocus fit_yield_locus(const std::vector<StressPoint>& failure, const StressPoint& preshear);

}  // namespace silodem
