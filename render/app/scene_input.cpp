#include "render/app/scene_input.h"

#include <stdexcept>

#include <fmt/core.h>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"

namespace rugosim::app {

std::optional<LoadedScene> load_scene_or_report(const std::string& path,
                                                const AccuracyOverride& accuracy, int threads) {
  SceneLoad load = load_scene_file(path);
  std::vector<SceneError> errors = load.errors;
  SceneWorld built;
  if (load.ok()) {
    if (accuracy.preset) load.scene.accuracy = AccuracySpec{*accuracy.preset, {}};
    for (const auto& [key, value] : accuracy.knobs)
      load.scene.accuracy.knobs[key] = value;
    try {
      (void)world_settings(load.scene);
    } catch (const std::invalid_argument& e) {
      // Only the options can get here: the loader checked the scene's own knobs.
      fmt::print(stderr, "error: {} (with the accuracy options given)\n", e.what());
      return std::nullopt;
    }
    built = build_world(load.scene, path, threads);
    errors = built.errors;
  }
  if (!errors.empty()) {
    for (const SceneError& e : errors)
      fmt::print(stderr, "error: {}\n", e.describe());
    fmt::print(stderr, "{}: {} error{}; the scene was not used\n", path, errors.size(),
               errors.size() == 1 ? "" : "s");
    return std::nullopt;
  }
  return LoadedScene{std::move(load.scene), std::move(built.world)};
}

}  // namespace rugosim::app
