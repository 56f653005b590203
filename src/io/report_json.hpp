// SPDX-License-Identifier: MIT
// The derived numbers of a case (what `silodem check --json` prints), as JSON via toml++'s JSON
// formatter.
#pragma once
#include <string>

#include "io/config/case.hpp"
#include "scenario/setup.hpp"

namespace silodem {

std::string case_report_json(const Case& c, const CaseReport& r);
std::string case_report_text(const Case& c, const CaseReport& r);

}  // namespace silodem
