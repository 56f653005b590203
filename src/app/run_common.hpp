// SPDX-License-Identifier: MIT
// Helpers shared by the run commands (app-internal).
#pragma once
#include <toml++/toml.h>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "core/bytes.hpp"
#include "io/atomic_file.hpp"
#include "io/config/case.hpp"
#include "io/run_dir.hpp"
#include "scenario/layered_filling.hpp"
#include "scenario/setup.hpp"

namespace silodem::app {

// The table as JSON text, ending in a newline.
std::string to_json(const toml::table& t);
// Creates DIR (refusing a non-empty one) with a copy of the case and its derived numbers.
std::filesystem::path prepare_out(const RunOptions& o, const Case& c, const CaseReport& report);

int run_silo(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model);
int resume_silo(const RunOptions& o);

// A run directory's checkpoint, opened (io/run_dir.hpp): the case as the directory holds it
// (case.toml, overrides.txt, relative paths as from the original case file), the checkpoint's
// head and a reader at the components' bytes. Refuses a directory without a checkpoint, a file
// that is truncated, foreign, of another version or whose head is damaged, or a case changed since
// (unless `force`), with an InputError naming `option`. Damage in the components' bytes shows when
// they are read.
struct RunCheckpoint {
  std::string case_path;
  std::vector<std::string> overrides;
  std::string base_dir;  // where the original case file was: relative paths start there
  RunHead head;
  ByteReader reader{{}};
  Case c;
};
RunCheckpoint open_run_checkpoint(const std::filesystem::path& dir, bool force, const char* option);

}  // namespace silodem::app
