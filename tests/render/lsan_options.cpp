// Under the asan preset: Mesa's llvmpipe keeps allocations made from its JIT-compiled code for
// the life of the process, which LeakSanitizer can neither attribute (an unknown module) nor
// suppress by name. The render suite therefore ignores allocations made on its main thread
// (where the contexts, shaders and draws run); AddressSanitizer's other checks stay on.
// Without sanitizers the weak symbol is null and nothing happens.
extern "C" void __lsan_disable() __attribute__((weak));

namespace {

struct DisableLeakChecks {
  DisableLeakChecks() {
    if (&__lsan_disable != nullptr) __lsan_disable();
  }
};
const DisableLeakChecks kDisableLeakChecks;

}  // namespace
