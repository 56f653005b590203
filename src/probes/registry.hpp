// SPDX-License-Identifier: MIT
// THE list of probes (registry.cpp): one line per probe.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "probes/probe.hpp"

namespace silodem {

struct ProbeEntry {
  std::string name;
  std::string doc;
  std::unique_ptr<Probe> (*make)(const ProbeSpec& spec, const ProbeSite& site);
};

const std::vector<ProbeEntry>& probe_registry();
// The probes of a case (all registered ones when [probes] every > 0, none otherwise).
std::vector<std::unique_ptr<Probe>> make_probes(const ProbeSpec& spec, const ProbeSite& site);

}  // namespace silodem
