#include "render/app/sigint_guard.h"

namespace rugosim::app {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "stored from a signal handler");

extern "C" void on_sigint(int) {
  g_interrupted.store(true, std::memory_order_relaxed);
}

}  // namespace

SigintGuard::SigintGuard() {
  g_interrupted = false;
  struct sigaction action {};
  action.sa_handler = on_sigint;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, &previous_);
}

SigintGuard::~SigintGuard() {
  ::sigaction(SIGINT, &previous_, nullptr);
}

const std::atomic<bool>& SigintGuard::interrupted() {
  return g_interrupted;
}

}  // namespace rugosim::app
