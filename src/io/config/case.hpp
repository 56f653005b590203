// SPDX-License-Identifier: MIT
// A whole case, as io/config makes it from a TOML file: the scenario's part (ScenarioCase, which
// the scenario layer reads), what the probes are told (ProbeSpec) and what the writers of a run
// read ([output], the measured outlet data). Each layer sees only its own part.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/schema.hpp"
#include "probes/probe_spec.hpp"
#include "scenario/case.hpp"
#include "scenario/outlet_stats.hpp"

namespace silodem {

struct OutputSpec {
  long every = 0;                  // steps between rows of trajectory.csv; 0 = final state only
  std::vector<std::uint64_t> ids;  // particles to write; empty = all
  double vtk_interval = 0.0;       // s between ParaView frames of a silo run; 0 = none
  std::string measured;            // measured outlet data (CSV), resolved against the case file
  SourcePlace measured_place;
};

struct Case : ScenarioCase {
  OutputSpec output;
  MeasuredData measured;
  ProbeSpec probes;
  // Where the probes look: the silo's extent.
  ProbeSite probe_site() const { return {silo.geometry.top_radius()}; }
};

namespace config {
// The [output] keys, bound to OutputSpec's members (`measured` is resolved and read by the loader).
const std::vector<Bound<OutputSpec>>& output_fields();
}  // namespace config

}  // namespace silodem
