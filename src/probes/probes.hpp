// SPDX-License-Identifier: MIT
// Factories of the probes, one per file; registry.cpp lists them.
#pragma once
#include <memory>

#include "probes/probe.hpp"

namespace silodem {

std::unique_ptr<Probe> make_slab_probe(const ProbeSpec& spec, const ProbeSite& site);
std::unique_ptr<Probe> make_velocity_profile_probe(const ProbeSpec& spec, const ProbeSite& site);
std::unique_ptr<Probe> make_adhesion_probe(const ProbeSpec& spec, const ProbeSite& site);
std::unique_ptr<Probe> make_cohesion_force_probe(const ProbeSpec& spec, const ProbeSite& site);
std::unique_ptr<Probe> make_level_probe(const ProbeSpec& spec, const ProbeSite& site);
std::unique_ptr<Probe> make_coordination_probe(const ProbeSpec& spec, const ProbeSite& site);

}  // namespace silodem
