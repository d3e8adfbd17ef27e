#include <string>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "render/app/commands.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"

namespace rugosim::app {

int run_validate(const std::string& scene_path) {
  const std::optional<LoadedScene> loaded = load_scene_or_report(scene_path);
  if (!loaded) return kExitUsage;
  const World& world = *loaded->world;
  // The run the scene asks for must be one the commands can make (run_length.h).
  const RunFrames run =
      run_frames(loaded->scene.duration, "/world/duration", loaded->scene.render.fps, "/render/fps",
                 world.settings().min_step);
  if (!run.error.empty()) {
    fmt::print(stderr, "error: {}: {}\n{}: 1 error; the scene was not used\n", scene_path,
               run.error, scene_path);
    return kExitUsage;
  }
  std::size_t fixed = 0, segments = 0;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    fixed += world.body(i).fixed() ? 1u : 0u;
    segments += world.body(i).curve().size();
  }
  // The preset, and the scene's own knobs on top of it: "normal", "draft with max_step 0.002".
  std::string accuracy = loaded->scene.accuracy.preset;
  const char* joint = " with ";
  for (const auto& [key, value] : loaded->scene.accuracy.knobs) {
    accuracy += fmt::format("{}{} {:g}", joint, key, value);
    joint = ", ";
  }
  fmt::print("{}: valid scene \"{}\": {} bodies ({} fixed), {} segments, {} s at accuracy {}\n",
             scene_path, loaded->scene.name, world.body_count(), fixed, segments,
             loaded->scene.duration, accuracy);
  return kExitOk;
}

int run_info(const std::string& scene_path, bool json) {
  const std::optional<LoadedScene> loaded = load_scene_or_report(scene_path);
  if (!loaded) return kExitUsage;
  const World& world = *loaded->world;
  nlohmann::json bodies = nlohmann::json::array();
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& b = world.body(i);
    const ToleranceRange lambda = b.shape().tolerances().range();
    const Vec2 c = b.state().position;
    bodies.push_back({{"name", world.name(i)},
                      {"fixed", b.fixed()},
                      {"segments", b.curve().size()},
                      {"area", b.area()},
                      {"mass", b.mass()},
                      {"centroid", {c.x(), c.y()}},
                      {"inertia", b.inertia()},
                      {"lambda_range", {lambda.lo, lambda.hi}},
                      {"tree_depth", b.shape().tree().depth()},
                      {"bounding_radius", b.bounding_radius()}});
  }
  if (json) {
    fmt::print("{}\n", nlohmann::json{{"scene", loaded->scene.name}, {"bodies", bodies}}.dump(2));
    return kExitOk;
  }
  fmt::print("scene \"{}\" ({}), {} bodies; units m, kg and s per unit thickness\n",
             loaded->scene.name, scene_path, world.body_count());
  fmt::print("{:<16} {:>5} {:>8} {:>11} {:>11} {:>23} {:>11} {:>21} {:>5}\n", "body", "fixed",
             "segments", "area", "mass", "centroid", "inertia", "lambda range", "depth");
  for (const nlohmann::json& b : bodies) {
    fmt::print(
        "{:<16} {:>5} {:>8} {:>11.5g} {:>11.5g} {:>11.5g} {:>11.5g} {:>11.5g} {:>10.3g} "
        "{:>10.3g} {:>5}\n",
        b["name"].get<std::string>(), b["fixed"].get<bool>() ? "yes" : "no",
        b["segments"].get<std::size_t>(), b["area"].get<double>(), b["mass"].get<double>(),
        b["centroid"][0].get<double>(), b["centroid"][1].get<double>(), b["inertia"].get<double>(),
        b["lambda_range"][0].get<double>(), b["lambda_range"][1].get<double>(),
        b["tree_depth"].get<int>());
  }
  return kExitOk;
}

}  // namespace rugosim::app
