// SPDX-License-Identifier: MIT
// libFuzzer target over the case-file loader (issue 5): any text must either load (and derive
// its numbers) or be refused with an InputError. Anything else - a crash, another exception, a
// sanitizer report, a leak - is a bug. Build: cmake --preset fuzz; run: scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "io/config/load.hpp"
#include "scenario/setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const silodem::Case c = silodem::config::load_case_text(text, "fuzz.toml");
    silodem::ContactModel model;
    (void)silodem::derive_case(c, &model);
  } catch (const silodem::InputError&) {
    // refused with a message: fine
  }
  return 0;
}
