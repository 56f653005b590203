// SPDX-License-Identifier: MIT
// Helpers shared by the run commands (app-internal).
#pragma once
#include <toml++/toml.h>
#include <filesystem>
#include <string>

#include "app/commands.hpp"
#include "scenario/setup.hpp"

namespace silodem::app {

// Writes "<path>.partial" and renames it: a reader never sees a half-written file.
void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);  // the whole file ("" if missing)
std::string to_json(const toml::table& t);
// Creates DIR (refusing a non-empty one) with a copy of the case and its derived numbers.
std::filesystem::path prepare_out(const RunOptions& o, const Case& c, const CaseReport& report);

int run_silo(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model);
int resume_silo(const RunOptions& o);

}  // namespace silodem::app
