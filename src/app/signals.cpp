// SPDX-License-Identifier: MIT
#include "app/signals.hpp"

#include <atomic>
#include <csignal>

namespace silodem::app {
namespace {

// Set by the handler, read by the time loop (which may run on another thread than the one the
// signal interrupts): a lock-free atomic is both async-signal-safe and race-free.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int sig) {
  g_signal.store(sig);
  std::signal(sig, SIG_DFL);  // a second signal ends the program at once
}

}  // namespace

int stop_signal() {
  return g_signal.load();
}

void default_signals() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

SignalGuard::SignalGuard() {
  g_signal.store(0);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

SignalGuard::~SignalGuard() {
  default_signals();
}

}  // namespace silodem::app
