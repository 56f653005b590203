// SPDX-License-Identifier: MIT
// TOML case file -> Case. Every key is checked for type, unit and range; unknown keys are refused
// with a suggestion; errors are InputError with file:line:column.
#pragma once
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "io/config/case.hpp"

namespace silodem::config {

// `overrides`: "key=value" items (--set), applied before validation. Relative paths in the case
// (`[output] measured`) are resolved against `base_dir`, by default the case file's folder.
Case load_case_file(const std::string& path, const std::vector<std::string>& overrides = {},
                    const std::string& base_dir = {});
// Applies one --set item ("a.b.c=value", coal[1].x for an array of tables; the value in TOML
// syntax, a bare word taken as a string) to a parsed case file. InputError if it cannot.
void apply_override(toml::table& root, const std::string& item);
// `name` is used in error messages in place of a path.
Case load_case_text(const std::string& text, const std::string& name);

}  // namespace silodem::config
