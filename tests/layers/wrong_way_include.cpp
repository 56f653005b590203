// This file must not compile: it is built as part of the model layer (silodem_model) and includes
// a header of the engine, a layer to its right. The test layers_wrong_way_include_fails
// (tests/CMakeLists.txt) builds it and passes only if the compiler cannot find that header.
#include "engine/simulation.hpp"

int silodem_layers_wrong_way() {
  return 0;
}
