// SPDX-License-Identifier: MIT
#include "io/run_dir.hpp"

#include <fmt/format.h>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"

namespace fs = std::filesystem;

namespace silodem {

RunDir RunDir::create(const fs::path& dir, const std::string& case_path,
                      const std::vector<std::string>& overrides, const std::string& check_json,
                      const char* option) {
  if (fs::exists(dir) && !(fs::is_directory(dir) && fs::is_empty(dir)))
    throw InputError({}, option,
                     fmt::format("'{}' exists and is not empty; refusing to overwrite (choose a "
                                 "new directory)",
                                 dir.string()));
  fs::create_directories(dir);
  fs::copy_file(case_path, dir / "case.toml", fs::copy_options::overwrite_existing);
  write_text(dir / "case_source.txt", fs::absolute(case_path).string());
  std::string text;
  for (const auto& s : overrides) text += s + "\n";
  if (!text.empty()) write_text(dir / "overrides.txt", text);
  write_text(dir / "check.json", check_json);
  return RunDir(dir);
}

std::vector<std::string> RunDir::overrides() const {
  std::vector<std::string> v;
  std::istringstream in(read_text(dir_ / "overrides.txt"));
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) v.push_back(line);
  return v;
}

std::string RunDir::case_dir() const {
  return fs::path(read_text(dir_ / "case_source.txt")).parent_path().string();
}

std::uint64_t RunDir::case_hash() const {
  return text_hash(read_text(dir_ / "case.toml") + "\n--\n" + read_text(dir_ / "overrides.txt"));
}

bool RunDir::has_checkpoint() const {
  return fs::is_regular_file(dir_ / "checkpoint.bin");
}

void RunDir::write_checkpoint(const RunHead& head,
                              const std::function<void(ByteWriter&)>& body) const {
  ByteWriter w;
  w.put(head.case_hash);
  w.put(std::int32_t(head.threads));
  if (head.phase == RunHead::Phase::Fill) {
    w.tag("FILP");
    w.put(head.wall);
  } else {
    w.tag("FILD");
    w.put(head.wall);
    head.fill.save(w);
  }
  body(w);
  silodem::write_checkpoint((dir_ / "checkpoint.bin").string(), w);
}

ByteReader RunDir::read_checkpoint(RunHead& head) const {
  const std::string file = (dir_ / "checkpoint.bin").string();
  ByteReader r = silodem::read_checkpoint(file);
  try {
    head.case_hash = r.get<std::uint64_t>();
    head.threads = r.get<std::int32_t>();
    if (r.next_is("FILP")) {
      r.tag("FILP");
      head.phase = RunHead::Phase::Fill;
      r.get(head.wall);
    } else if (r.next_is("FILD")) {
      r.tag("FILD");
      head.phase = RunHead::Phase::Discharge;
      r.get(head.wall);
      head.fill.load(r);
    } else {  // written before the fill block held the segments: they stay empty
      r.tag("FILL");
      head.phase = RunHead::Phase::Discharge;
      r.get(head.wall);
      FillReport& f = head.fill;
      r.get(f.particles), r.get(f.mass), r.get(f.settle_time), r.get(f.max_boundary_offset);
      f.warnings.resize(r.get_count(sizeof(std::uint64_t)));
      for (auto& m : f.warnings) r.get(m);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: damaged run checkpoint ({})", file, e.what()));
  }
  return r;
}

void RunDir::remove_checkpoint() const {
  fs::remove(dir_ / "checkpoint.bin");
}

}  // namespace silodem
