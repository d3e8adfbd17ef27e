// Loading a scene for a command: the file read and validated, the World built, and on failure
// every error printed to stderr (file, JSON path, expectation) for exit code 2.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"

namespace rugosim::app {

struct LoadedScene {
  Scene scene;
  std::unique_ptr<World> world;
};

// What the command line says of the accuracy (--accuracy and the knob options).
struct AccuracyOverride {
  std::optional<std::string> preset;    // replaces the scene's accuracy, knobs and all
  std::map<std::string, double> knobs;  // then override single knobs (accuracy_knobs() keys)
};

// nullopt after printing the errors. `accuracy` is applied to the scene before the World is
// built (the caller has checked the preset's name and each knob's range); a time-of-impact
// tolerance left above the longest step is reported as an error too. The World detects
// collisions on `threads` threads (--threads).
std::optional<LoadedScene> load_scene_or_report(const std::string& path,
                                                const AccuracyOverride& accuracy = {},
                                                int threads = 1);

// Exit codes of INTERFACE.md.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInterrupted = 130;

}  // namespace rugosim::app
