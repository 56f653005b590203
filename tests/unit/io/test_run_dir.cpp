// SPDX-License-Identifier: MIT
// The run directory's one writer and reader (issue 18, item 3): what `run` writes before its first
// step comes back as written; a checkpoint's head (phase, wall time, the finished fill with its
// segments) round-trips and leaves the reader at the components' bytes; a damaged head or a
// foreign file is an error naming the file.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "io/checkpoint.hpp"
#include "io/run_dir.hpp"

namespace fs = std::filesystem;
using namespace silodem;

namespace {

fs::path fresh(const char* name) {
  const fs::path d = fs::temp_directory_path() /
                     (std::string("silodem_rundir_") + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

fs::path case_file(const fs::path& where) {
  fs::create_directories(where);
  const fs::path p = where / "my_case.toml";
  std::ofstream(p) << "title = \"t\"\n";
  return p;
}

TEST(RunDir, CreateWritesTheCaseItsSourceAndOverridesAndRefusesAFullDirectory) {
  const fs::path base = fresh("create");
  const fs::path src = case_file(base / "cases");
  const RunDir d = RunDir::create(base / "run", src.string(), {"a.b=1", "c=\"x\""}, "{}\n");
  EXPECT_EQ(d.overrides(), (std::vector<std::string>{"a.b=1", "c=\"x\""}));
  EXPECT_EQ(fs::path(d.case_dir()), fs::absolute(base / "cases"));
  EXPECT_TRUE(fs::exists(d.case_file()));
  EXPECT_TRUE(fs::exists(base / "run" / "check.json"));
  EXPECT_FALSE(d.has_checkpoint());
  // The hash follows the case and its overrides.
  const std::uint64_t h = d.case_hash();
  std::ofstream(base / "run" / "overrides.txt", std::ios::app) << "d=2\n";
  EXPECT_NE(d.case_hash(), h);
  EXPECT_THROW(RunDir::create(base / "run", src.string(), {}, "{}\n"), InputError);
  fs::remove_all(base);
}

TEST(RunDir, ACheckpointHeadRoundTripsWithTheFillSegments) {
  const fs::path base = fresh("head");
  const RunDir d = RunDir::create(base / "run", case_file(base).string(), {}, "{}\n");
  RunHead h;
  h.case_hash = 0x1234abcdULL;
  h.threads = 2;
  h.phase = RunHead::Phase::Discharge;
  h.wall = 12.5;
  h.fill.segments.resize(2);
  h.fill.segments[1].coal = 1;
  h.fill.segments[1].mass = 0.75;
  h.fill.particles = 99;
  h.fill.mass = 1.5;
  h.fill.warnings = {"w1"};
  d.write_checkpoint(h, [](ByteWriter& w) { w.put(std::int32_t(42)); });
  ASSERT_TRUE(d.has_checkpoint());
  RunHead r;
  ByteReader rest = d.read_checkpoint(r);
  EXPECT_EQ(r.case_hash, h.case_hash);
  EXPECT_EQ(r.threads, 2);
  EXPECT_EQ(r.phase, RunHead::Phase::Discharge);
  EXPECT_EQ(r.wall, 12.5);
  ASSERT_EQ(r.fill.segments.size(), 2u);
  EXPECT_EQ(r.fill.segments[1].coal, 1);
  EXPECT_EQ(r.fill.segments[1].mass, 0.75);
  EXPECT_EQ(r.fill.particles, 99);
  EXPECT_EQ(r.fill.warnings, std::vector<std::string>{"w1"});
  EXPECT_EQ(rest.get<std::int32_t>(), 42);  // the components' bytes follow the head
  EXPECT_TRUE(rest.done());

  h.phase = RunHead::Phase::Fill;  // during the fill: no fill report
  d.write_checkpoint(h, [](ByteWriter& w) { w.put(std::int32_t(7)); });
  ByteReader rest2 = d.read_checkpoint(r);
  EXPECT_EQ(r.phase, RunHead::Phase::Fill);
  EXPECT_EQ(rest2.get<std::int32_t>(), 7);
  d.remove_checkpoint();
  EXPECT_FALSE(d.has_checkpoint());
  fs::remove_all(base);
}

TEST(RunDir, ADamagedHeadIsAnErrorNamingTheFile) {
  const fs::path base = fresh("damaged");
  const RunDir d = RunDir::create(base / "run", case_file(base).string(), {}, "{}\n");
  // A valid checkpoint file (magic, version, length) whose body is not a run checkpoint: empty.
  write_checkpoint((base / "run" / "checkpoint.bin").string(), ByteWriter{});
  RunHead r;
  try {
    d.read_checkpoint(r);
    FAIL() << "no error for a checkpoint without a run head";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint.bin"), std::string::npos) << e.what();
  }
  fs::remove_all(base);
}

// The discharge block as silodem wrote it before acf744d ("FILL": no segments), with `warnings`
// as the count of the warning strings that follow (one is written).
[[gnu::noinline]] ByteWriter legacy_head(std::uint64_t warnings) {
  ByteWriter w;
  w.put(std::uint64_t(77));  // case hash
  w.put(std::int32_t(1));    // threads
  w.tag("FILL");
  w.put(3.5);                                // wall
  w.put(long(10)), w.put(0.25), w.put(1.0);  // particles, mass, settle time
  w.put(0.002);                              // max boundary offset
  w.put(warnings), w.put(std::string("warn"));
  w.put(std::int32_t(5));  // the components' bytes
  return w;
}

TEST(RunDir, ACheckpointOfTheOlderFormatIsReadWithoutSegments) {
  const fs::path base = fresh("legacy");
  const RunDir d = RunDir::create(base / "run", case_file(base).string(), {}, "{}\n");
  write_checkpoint((base / "run" / "checkpoint.bin").string(), legacy_head(1));
  RunHead h;
  ByteReader rest = d.read_checkpoint(h);
  EXPECT_EQ(h.case_hash, 77u);
  EXPECT_EQ(h.phase, RunHead::Phase::Discharge);
  EXPECT_EQ(h.wall, 3.5);
  EXPECT_EQ(h.fill.particles, 10);
  EXPECT_EQ(h.fill.mass, 0.25);
  EXPECT_EQ(h.fill.max_boundary_offset, 0.002);
  EXPECT_TRUE(h.fill.segments.empty());
  EXPECT_EQ(h.fill.warnings, std::vector<std::string>{"warn"});
  EXPECT_EQ(rest.get<std::int32_t>(), 5);
  // A damaged count of warnings is refused before anything is allocated for it.
  write_checkpoint((base / "run" / "checkpoint.bin").string(), legacy_head(1ull << 40));
  EXPECT_THROW(d.read_checkpoint(h), std::runtime_error);
  fs::remove_all(base);
}

}  // namespace
