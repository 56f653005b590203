// SPDX-License-Identifier: MIT
// Observers of the time loop: a phase and a schedule. The loop does not know what they do.
#pragma once
#include <functional>
#include <string>

namespace silodem {

class Simulation;

enum class Phase { StepBegin, StepEnd };

struct Hook {
  std::string name;
  Phase phase = Phase::StepEnd;
  long every = 1;  // run when step_count % every == 0
  std::function<void(Simulation&)> run;
};

}  // namespace silodem
