// SPDX-License-Identifier: MIT
// `silodem check CASE.toml [--json]`: validate the case and print the derived quantities.
#include <fmt/format.h>

#include "app/commands.hpp"
#include "io/config/load.hpp"
#include "io/report_json.hpp"

namespace silodem::app {

int check_command(const std::string& case_path, bool json,
                  const std::vector<std::string>& overrides) {
  const Case c = config::load_case_file(case_path, overrides);
  const CaseReport r = derive_case(c);
  fmt::print("{}", json ? case_report_json(c, r) : case_report_text(c, r));
  return kExitOk;
}

}  // namespace silodem::app
