// Where the program-level tests find the rugosim program and the source tree: ctest passes
// RUGOSIM_PROGRAM and RUGOSIM_SOURCE_DIR (tests/CMakeLists.txt).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace rugosim::testing {

inline std::filesystem::path source_dir() {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::path(".");
}

inline std::string program() {
  const char* p = std::getenv("RUGOSIM_PROGRAM");
  return p != nullptr ? p : "rugosim";
}

}  // namespace rugosim::testing
