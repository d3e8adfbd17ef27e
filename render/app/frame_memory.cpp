#include "render/app/frame_memory.h"

// Any C library header defines __GLIBC__ (through <features.h>); without one the test below is
// always false and the thresholds were never set (measured: mallopt was not called until this).
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rugosim::app {

void keep_frame_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
#endif
}

}  // namespace rugosim::app
