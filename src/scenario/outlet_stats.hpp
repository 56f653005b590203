// SPDX-License-Identifier: MIT
// Outlet statistics per time bin (PHYSICS.md 5-6): mass, mass flow rate, cumulative mass, mass
// fraction of each coal and the calorific value of the mix (Eq. 17, generalised to N coals:
// Q = sum_c x_c Q_c).
#pragma once
#include <vector>

#include "scenario/discharge.hpp"

namespace silodem {

struct OutletBin {
  double t_start = 0.0, t_end = 0.0;
  double mass = 0.0, rate = 0.0, cumulative = 0.0;
  std::vector<double> fraction;  // per coal; NaN when nothing left in the bin
  double calorific = 0.0;        // kcal/kg; NaN when nothing left in the bin
};

std::vector<OutletBin> outlet_bins(const std::vector<OutletRecord>& out, double bin, double t_end,
                                   const std::vector<double>& heating_values);

// Eq. 17 over a mass inventory: sum_c m_c Q_c / sum_c m_c.
double mixture_calorific(const std::vector<double>& mass_per_coal,
                         const std::vector<double>& heating_values);

}  // namespace silodem
