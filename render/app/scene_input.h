// Loading a scene for a command: the file read and validated, the World built, and on failure
// every error printed to stderr (file, JSON path, expectation) for exit code 2.
#pragma once

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

// nullopt after printing the errors. `accuracy`, when given, replaces the scene's preset
// before the World is built (the caller has checked it is a preset name).
std::optional<LoadedScene> load_scene_or_report(const std::string& path,
                                                const std::optional<std::string>& accuracy = {});

// Exit codes of INTERFACE.md.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInterrupted = 130;

}  // namespace rugosim::app
