// SPDX-License-Identifier: MIT
// SIGINT and SIGTERM as a request to stop at the next checkpoint: long commands (`run`,
// `shear-test`) install the handler while they run and poll stop_signal() between steps; a second
// signal ends the program at once.
#pragma once

namespace silodem::app {

// The signal that asked to stop, 0 if none since the last SignalGuard was made.
int stop_signal();
// Puts back the default handlers (Ctrl-C then ends the program at once).
void default_signals();

// Installs the handler for its lifetime (and clears an earlier request).
struct SignalGuard {
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;
};

}  // namespace silodem::app
