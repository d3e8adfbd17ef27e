// The git commit this program was built from (cmake/WriteBuildId.cmake): a 40-digit hash,
// with "-dirty-<12 hex digits of the diff's SHA-1>" when the work tree had changes, or "unknown"
// when built outside a checkout.
#pragma once

namespace rugosim::app {

const char* build_id();

}  // namespace rugosim::app
