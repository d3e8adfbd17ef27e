#include "render/app/sigint_guard.h"

namespace rugosim::app {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "stored from a signal handler");

extern "C" void on_sigint(int) {
  g_interrupted.store(true, std::memory_order_relaxed);
}

// Clears the flag before the handler is installed, so that only a SIGINT from now on counts;
// returns SIGINT.
int sigint_from_now() {
  g_interrupted = false;
  return SIGINT;
}

}  // namespace

ScopedSignalHandler::ScopedSignalHandler(int signal, void (*handler)(int)) : signal_(signal) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal_, &action, &previous_);
}

ScopedSignalHandler::~ScopedSignalHandler() {
  ::sigaction(signal_, &previous_, nullptr);
}

SigintGuard::SigintGuard() : handler_(sigint_from_now(), on_sigint) {}

SigintGuard::~SigintGuard() = default;

const std::atomic<bool>& SigintGuard::interrupted() {
  return g_interrupted;
}

}  // namespace rugosim::app
