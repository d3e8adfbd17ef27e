// Ctrl-C during a long run (INTERFACE.md: exit 130 after closing outputs properly): while a
// SigintGuard lives, SIGINT only sets a flag that the run polls; the previous handler comes
// back when it ends.
#pragma once

#include <atomic>
#include <csignal>

namespace rugosim::app {

class SigintGuard {
 public:
  SigintGuard();
  ~SigintGuard();
  SigintGuard(const SigintGuard&) = delete;
  SigintGuard& operator=(const SigintGuard&) = delete;

  // Set by the handler (lock-free, so a signal handler may store to it).
  static const std::atomic<bool>& interrupted();

 private:
  struct sigaction previous_ {};
};

}  // namespace rugosim::app
