// SPDX-License-Identifier: MIT
// Measured outlet data: a CSV with a header row naming t_s and rate_kg_s and/or calorific_kcal_kg
// (other columns are ignored; an empty cell = not measured at that time).
#pragma once
#include <string>

#include "scenario/outlet_stats.hpp"

namespace silodem {

// Errors name the CSV's file:line:column (or `from`, the case-file key, when it cannot be read).
MeasuredData load_measured_csv(const std::string& path, const SourcePlace& from);

}  // namespace silodem
