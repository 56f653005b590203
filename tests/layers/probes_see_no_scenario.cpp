// This file must not compile: it is built as part of the probes layer (silodem_probes), which sits
// on the engine beside the scenario layer and gets what it needs from io's Case (ProbeSpec,
// ProbeSite). The test layers_probes_see_no_scenario (tests/CMakeLists.txt) builds it and passes
// only if the compiler cannot find the scenario's header.
#include "scenario/case.hpp"

int silodem_layers_probes_see_no_scenario() {
  return 0;
}
