// SPDX-License-Identifier: MIT
// A run directory (docs/runs.md): the files `silodem run` writes into it before the first step
// (case.toml, case_source.txt, overrides.txt, check.json) and its checkpoint.bin, written and read
// here only. The state of a directory (absent, resumable, finished, ...) is run_state()
// (io/run_metrics.hpp), from summary.json read as JSON.
//
// checkpoint.bin (io/checkpoint.hpp's header: magic, format version, length) holds a RunHead
// (case hash, threads, then "FILP" and the wall time during the fill, or "FILD", the wall time and
// the finished fill's report in the discharge; "FILL", the same without the segments, is read as
// written by silodem before acf744d: a run resumed from it has no segments in its fill report, so
// the summary's inventory calorific value is NaN for a fill without measured bulk densities),
// then the components' own bytes in a fixed order: during the fill
// FillProgress and the Simulation; in the discharge the Simulation, the Discharge and the
// observers (probes, frames).
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/bytes.hpp"
#include "scenario/layered_filling.hpp"

namespace silodem {

// What a run checkpoint says about the run as a whole.
struct RunHead {
  enum class Phase { Fill, Discharge };
  std::uint64_t case_hash = 0;  // of case.toml + overrides.txt when the run started
  int threads = 0;              // the run's thread count (the summation order)
  Phase phase = Phase::Fill;
  double wall = 0.0;  // s of wall time the run had used
  FillReport fill;    // the finished fill (Phase::Discharge only)
};

class RunDir {
 public:
  explicit RunDir(std::filesystem::path dir) : dir_(std::move(dir)) {}
  const std::filesystem::path& path() const { return dir_; }

  // A new run: refuses a directory that exists and is not empty (InputError on `option`), then
  // copies the case file and writes case_source.txt, overrides.txt (only with --set) and
  // check.json.
  static RunDir create(const std::filesystem::path& dir, const std::string& case_path,
                       const std::vector<std::string>& overrides, const std::string& check_json,
                       const char* option = "--out");

  // The case as the directory holds it.
  std::string case_file() const { return (dir_ / "case.toml").string(); }
  std::vector<std::string> overrides() const;
  // Where the original case file was (relative paths in the case start there).
  std::string case_dir() const;
  // FNV-1a of case.toml and overrides.txt: a changed case is refused on resume.
  std::uint64_t case_hash() const;

  bool has_checkpoint() const;
  // checkpoint.bin: the head, then what `body` writes (atomically; the previous one stays intact
  // until the new one is complete).
  void write_checkpoint(const RunHead& head, const std::function<void(ByteWriter&)>& body) const;
  // Reads checkpoint.bin and its head; the reader is left at the components' bytes. Throws
  // std::runtime_error naming the file when it is missing, truncated, foreign or of another
  // format version.
  ByteReader read_checkpoint(RunHead& head) const;
  void remove_checkpoint() const;

 private:
  std::filesystem::path dir_;
};

}  // namespace silodem
