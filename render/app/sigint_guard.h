// Ctrl-C during a long run (INTERFACE.md: exit 130 after closing outputs properly): while a
// SigintGuard lives, SIGINT only sets a flag that the run polls; the previous handler comes
// back when it ends.
#pragma once

#include <atomic>
#include <csignal>

namespace rugosim::app {

// While it lives, `handler` (a function, SIG_IGN or SIG_DFL) handles `signal`; the previous
// disposition comes back when it ends.
class ScopedSignalHandler {
 public:
  ScopedSignalHandler(int signal, void (*handler)(int));
  ~ScopedSignalHandler();
  ScopedSignalHandler(const ScopedSignalHandler&) = delete;
  ScopedSignalHandler& operator=(const ScopedSignalHandler&) = delete;

 private:
  int signal_;
  struct sigaction previous_ {};
};

class SigintGuard {
 public:
  SigintGuard();
  ~SigintGuard();
  SigintGuard(const SigintGuard&) = delete;
  SigintGuard& operator=(const SigintGuard&) = delete;

  // Set by the handler (lock-free, so a signal handler may store to it).
  static const std::atomic<bool>& interrupted();

 private:
  ScopedSignalHandler handler_;
};

}  // namespace rugosim::app
