// What must hold for any input given to the scene loader, shared by the fuzz target
// (tests/fuzz/scene_loader_fuzz.cpp) and the test that replays what it found
// (tests/scene/fuzz_regression_test.cpp), so both judge an input the same way.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

namespace rugosim::testing {

// Valid scenes above these sizes are not built: the loader accepts up to 100,000 segments per
// body, and building that many under sanitizers takes seconds, which would make a fuzz run
// measure slowness instead of correctness. A few thousand segments still exercise every path.
inline constexpr std::size_t kMaxFuzzSegmentsPerBody = 2000;
inline constexpr std::size_t kMaxFuzzSegmentsTotal = 20000;

inline bool too_large_to_build(const Scene& scene) {
  std::size_t total = 0;
  for (const BodySpec& body : scene.bodies) {
    if (body.shape.segments > kMaxFuzzSegmentsPerBody) return true;
    total += body.shape.segments;
  }
  return total > kMaxFuzzSegmentsTotal;
}

// Empty when `error` is something a user can act on: it names the file, and either the JSON
// path of the value (RFC 6901, so it starts with '/') or, for a syntax error, the line.
// Otherwise says what is wrong with it.
inline std::string malformed(const SceneError& error) {
  if (error.file.empty()) return "no file";
  if (error.message.empty()) return "no message";
  const bool has_path = !error.path.empty() && error.path.front() == '/';
  if (!has_path && error.line <= 0) return "neither a JSON path starting with '/' nor a line";
  if (error.line < 0 || error.column < 0) return "a negative line or column";
  return {};
}

// The first malformed error of `errors`, described with what is wrong; empty when all are fine.
inline std::string first_malformed(const std::vector<SceneError>& errors) {
  for (const SceneError& error : errors) {
    const std::string why = malformed(error);
    if (!why.empty()) return why + ": " + error.describe();
  }
  return {};
}

}  // namespace rugosim::testing
