// SPDX-License-Identifier: MIT
// Checkpoint files: a header (magic, format version) and the bytes the components wrote.
// Written atomically: "<path>.partial", fsync, rename over the previous checkpoint (which stays
// intact until the new one is complete), fsync of the directory.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/bytes.hpp"

namespace silodem {

void write_checkpoint(const std::string& path, const ByteWriter& body);
// Throws std::runtime_error naming the file when it is missing, foreign or damaged.
ByteReader read_checkpoint(const std::string& path);

// FNV-1a 64 of some text (the case file and its overrides, to detect a changed case on resume).
std::uint64_t text_hash(const std::string& text);

}  // namespace silodem
