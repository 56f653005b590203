// SPDX-License-Identifier: MIT
// The one way silodem writes a whole file: "<path>.partial", optionally fsync, then rename over
// `path` (a reader sees the old file or the new one, never half of one), then, with `sync`, an
// fsync of the directory so that the rename itself survives a crash.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace silodem {

void write_atomically(const std::string& path, const std::vector<std::string_view>& parts,
                      bool sync);

// A text file written whole with write_atomically (no fsync), and read whole ("" if missing).
void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);

}  // namespace silodem
