// The git commit this program was built from (cmake/WriteBuildId.cmake): a 40-digit hash,
// with "-dirty" when the work tree had changes, or "unknown" when built outside a checkout.
#pragma once

namespace rugosim::app {

const char* build_id();

}  // namespace rugosim::app
