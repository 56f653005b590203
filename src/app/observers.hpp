// SPDX-License-Identifier: MIT
// The observers of a silo discharge: the probes, each streaming its rows into probe_<name>.csv,
// and the ParaView frames every vtk_interval seconds. Clock: seconds since the valve opened.
// Their state (probe accumulators, file sizes, frames) goes into the run's checkpoint.
#pragma once
#include <toml++/toml.h>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/config/case.hpp"
#include "io/csv.hpp"
#include "io/vtk.hpp"
#include "probes/registry.hpp"

namespace silodem::app {

class Observers {
 public:
  // A new run: creates the files. t0: simulation time at the valve opening.
  Observers(const Case& c, const std::filesystem::path& out, double t0);
  // A resumed run: the probes' state and the files as they were at the checkpoint.
  Observers(const Case& c, const std::filesystem::path& out, double t0, ByteReader& r);
  void attach(Simulation& sim);
  void sample(const Simulation& sim);
  void frame(const Simulation& sim);
  void finish();             // final rows (time averages); files renamed to their final names
  void save(ByteWriter& w);  // flushes the files (their sizes go into the checkpoint)
  toml::array files() const;
  std::size_t frames() const { return pvd_ ? pvd_->frames() : 0; }

 private:
  const Case& c_;
  std::filesystem::path out_;
  double t0_;
  std::vector<std::unique_ptr<Probe>> probes_;
  std::vector<std::unique_ptr<CsvWriter>> files_;
  std::unique_ptr<PvdCollection> pvd_;
  double next_frame_ = 0.0;
};

}  // namespace silodem::app
