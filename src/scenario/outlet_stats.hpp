// SPDX-License-Identifier: MIT
// Outlet statistics per time bin (PHYSICS.md 5-6): mass, mass flow rate, cumulative mass, mass
// fraction of each coal and the calorific value of the mix (Eq. 17, generalised to N coals:
// Q = sum_c x_c Q_c).
#pragma once
#include <vector>

#include "scenario/discharge.hpp"

namespace silodem {

// Measured outlet data (optional): times with a mass flow rate and/or a calorific value.
struct MeasuredData {
  std::vector<double> t;          // s since the valve opened
  std::vector<double> rate;       // kg/s (NaN where not measured)
  std::vector<double> calorific;  // kcal/kg (NaN where not measured)
  bool has_rate = false, has_calorific = false;
};

struct OutletBin {
  double t_start = 0.0, t_end = 0.0;
  double mass = 0.0, rate = 0.0, cumulative = 0.0;
  std::vector<double> fraction;  // per coal; NaN when nothing left in the bin
  double calorific = 0.0;        // kcal/kg; NaN when nothing left in the bin
};

std::vector<OutletBin> outlet_bins(const std::vector<OutletRecord>& out, double bin, double t_end,
                                   const std::vector<double>& heating_values);

// Simulated bins against measured outlet data: for each measured point at time t, the bin with
// t_start <= t < t_end (points outside the bins, or whose bin or measurement is empty or zero,
// are skipped); relative error |sim - meas| / |meas|.
struct MeasuredErrors {
  int rate_points = 0, calorific_points = 0;
  double rate_max = 0.0, rate_mean = 0.0;            // NaN when no point compared
  double calorific_max = 0.0, calorific_mean = 0.0;  // NaN when no point compared
};
MeasuredErrors compare_with_measured(const std::vector<OutletBin>& bins, const MeasuredData& m);

// Eq. 17 over a mass inventory: sum_c m_c Q_c / sum_c m_c.
double mixture_calorific(const std::vector<double>& mass_per_coal,
                         const std::vector<double>& heating_values);

}  // namespace silodem
