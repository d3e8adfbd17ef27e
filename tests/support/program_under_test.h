// Where the program-level tests find the rugosim program and the source tree: ctest passes
// RUGOSIM_PROGRAM and RUGOSIM_SOURCE_DIR (tests/CMakeLists.txt).
#pragma once

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <unistd.h>

#include "support/scratch_dir.h"

namespace rugosim::testing {

inline std::filesystem::path source_dir() {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::path(".");
}

inline std::string program() {
  const char* p = std::getenv("RUGOSIM_PROGRAM");
  return p != nullptr ? p : "rugosim";
}

// A shell command line run to its end, stdout discarded.
struct CommandRun {
  int exit_code = -1;       // -1 when it did not exit normally
  std::string stderr_text;  // what it wrote to stderr
  double seconds = 0.0;     // wall time
};

// Runs `command_line` under timeout(1), so that a hang ends as exit 124 after `guard_seconds`
// instead of a stuck test, with stderr captured through `stderr_file`.
inline CommandRun run_command_line(const std::string& command_line,
                                   const std::filesystem::path& stderr_file,
                                   int guard_seconds = 60) {
  CommandRun r;
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(("timeout " + std::to_string(guard_seconds) + " " + command_line +
                                  " >/dev/null 2>" + stderr_file.string())
                                     .c_str());
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(stderr_file);
  std::ostringstream text;
  text << in.rdbuf();
  r.stderr_text = text.str();
  return r;
}

}  // namespace rugosim::testing
