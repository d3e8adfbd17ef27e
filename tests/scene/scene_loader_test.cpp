// Scene files (scene_loader.h, scene_world.h): the contract's example reads back with every
// value, defaults fill the rest, and every file of tests/scene/bad/ is rejected with an error at
// the JSON path its .expect file names (first line; empty for a syntax error, which carries a
// line and column instead) and a message containing its second line.
#include "engine/scene/scene_loader.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_world.h"

namespace rugosim {
namespace {

std::filesystem::path source_dir() {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::path(".");
}

// Loads and, when the file itself is valid, builds the World, as `rugosim validate` does.
std::vector<SceneError> all_errors(const std::string& path) {
  SceneLoad load = load_scene_file(path);
  if (!load.ok()) return load.errors;
  return build_world(load.scene, path).errors;
}

// The contract's example (INTERFACE.md), comments and all.
constexpr const char* kExample = R"({
  "version": 1,
  "name": "figure09",
  "world": {
    "gravity": [0, -9.81],     // m/s², default [0, -9.81]
    "duration": 4.0,           // s, > 0
    "seed": 7,                 /* drives every random choice */
    "accuracy": "normal",
    "q": 0.9,
    "friction_gain": 100.0
  },
  "materials": {
    "stone": { "density": 2500, "restitution": 0.3, "restitution_max": 0.6, "lambda_min": 0.001 }
  },
  "bodies": [
    {
      "name": "floor", "fixed": true,
      "shape": { "box": { "size": [6, 0.4], "segments": 32 } },
      "position": [0, -0.2], "angle": 0, "material": "stone",
      "rugosity": { "pattern": "type_1", "sigma": 0.004 }
    },
    {
      "name": "pebble",
      "shape": { "control_points": [[0.3,0],[0.2,0.25],[-0.1,0.3],[-0.3,0.05],[-0.2,-0.2],[0.1,-0.25]] },
      "position": [-1.5, 0.6], "velocity": [2.0, 0.0], "angular_velocity": 0.0,
      "material": { "density": 1200, "restitution": 0.2, "restitution_max": 0.5, "lambda_min": 0.0 },
      "rugosity": { "sigma": [0.002, 0.004, 0.006, 0.004, 0.002, 0.001] }
    }
  ],
  "render": {
    "size": [1280, 720], "fps": 30,
    "camera": { "center": [0, 0.5], "height": 3.0 },
    "background": "#f4f1ea",
    "overlays": ["rugosity", "contacts"]
  }
})";

TEST(SceneLoader, ReadsTheContractExample) {
  const SceneLoad load = parse_scene(kExample, "example.json");
  ASSERT_TRUE(load.ok()) << load.errors.front().describe();
  const Scene& s = load.scene;
  EXPECT_EQ(s.name, "figure09");
  EXPECT_EQ(s.gravity, Vec2(0.0, -9.81));
  EXPECT_EQ(s.duration, 4.0);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_EQ(s.accuracy.preset, "normal");
  EXPECT_TRUE(s.accuracy.knobs.empty());
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_TRUE(s.bodies[0].fixed);
  EXPECT_EQ(s.bodies[0].shape.kind, ShapeKind::kBox);
  EXPECT_EQ(s.bodies[0].material_name, "stone");
  EXPECT_EQ(s.bodies[0].material.density, 2500.0);
  EXPECT_EQ(s.bodies[0].material.lambda_min, 0.001);
  EXPECT_EQ(s.bodies[0].rugosity.pattern, RugosityPattern::kConstant);
  EXPECT_EQ(s.bodies[1].shape.control_points.size(), 6u);
  EXPECT_EQ(s.bodies[1].velocity, Vec2(2.0, 0.0));
  EXPECT_EQ(s.bodies[1].material.restitution, 0.2);
  EXPECT_EQ(s.bodies[1].rugosity.sigma.size(), 6u);
  EXPECT_FALSE(s.render.camera.automatic);
  EXPECT_EQ(s.render.camera.height, 3.0);
  EXPECT_EQ(s.render.overlays, (std::vector<std::string>{"rugosity", "contacts"}));

  const SceneWorld built = build_world(s, "example.json");
  ASSERT_TRUE(built.errors.empty()) << built.errors.front().describe();
  EXPECT_EQ(built.world->body_count(), 2u);
  EXPECT_EQ(built.world->name(1), "pebble");
  EXPECT_NEAR(built.world->body(1).origin_position().x(), -1.5, 1e-12);
}

TEST(SceneLoader, FillsDefaults) {
  const SceneLoad load = parse_scene(
      R"({"world": {"duration": 1}, "bodies": [{"name": "b", "shape": {"circle": {"radius": 1}},
          "material": {"restitution": 0.8}}]})",
      "scenes/defaults.json");
  ASSERT_TRUE(load.ok()) << load.errors.front().describe();
  const Scene& s = load.scene;
  EXPECT_EQ(s.name, "defaults");  // the file's stem
  EXPECT_EQ(s.gravity, Vec2(0.0, -9.81));
  EXPECT_EQ(s.seed, 0u);
  EXPECT_EQ(s.q, 0.9);
  EXPECT_EQ(s.friction_gain, 100.0);
  EXPECT_EQ(s.accuracy.preset, "normal");
  EXPECT_TRUE(s.accuracy.knobs.empty());
  EXPECT_EQ(s.bodies[0].shape.segments, 32u);
  EXPECT_EQ(s.bodies[0].material.density, Material::kDefaultDensity);
  // ε_max follows a bouncier ε up instead of making the material invalid.
  EXPECT_EQ(s.bodies[0].material.restitution_max, 0.8);
  EXPECT_TRUE(s.render.camera.automatic);
  EXPECT_EQ(s.render.width, 1280);
  EXPECT_EQ(s.render.fps, 30.0);
}

TEST(SceneLoader, ReportsEveryProblemInOnePass) {
  const SceneLoad load = parse_scene(
      R"({"world": {"duration": -1, "q": 2},
          "bodies": [{"name": "a", "shape": {"circle": {"radius": 0}},
                      "material": {"density": 0}}]})",
      "many.json");
  std::vector<std::string> paths;
  for (const SceneError& e : load.errors)
    paths.push_back(e.path);
  EXPECT_EQ(paths, (std::vector<std::string>{"/world/duration", "/world/q",
                                             "/bodies/0/shape/circle/radius",
                                             "/bodies/0/material/density"}));
}

TEST(SceneLoader, SyntaxErrorsCarryLineAndColumn) {
  const SceneLoad load =
      parse_scene("{\n  \"world\": {\"duration\": 2},\n  \"bodies\": [,]\n}\n", "broken.json");
  ASSERT_EQ(load.errors.size(), 1u);
  EXPECT_EQ(load.errors[0].line, 3);
  EXPECT_EQ(load.errors[0].column, 14);
  EXPECT_EQ(load.errors[0].describe().rfind("broken.json:3:14: invalid JSON", 0), 0u)
      << load.errors[0].describe();
}

TEST(SceneLoader, KeysWithSlashesAreEscapedInPaths) {
  const SceneLoad load = parse_scene(
      R"({"world": {"duration": 1}, "materials": {"a/b~c": {"density": -1}},
          "bodies": [{"name": "b", "shape": {"circle": {"radius": 1}}}]})",
      "escape.json");
  ASSERT_EQ(load.errors.size(), 1u);
  EXPECT_EQ(load.errors[0].path, "/materials/a~1b~0c/density");
}

TEST(SceneLoader, MissingFileAndDirectoryAreNamed) {
  const std::vector<SceneError> missing = all_errors("/no/such/scene.json");
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].describe(), "/no/such/scene.json: no such file");
  const std::string dir = (source_dir() / "tests").string();
  const std::vector<SceneError> directory = all_errors(dir);
  ASSERT_EQ(directory.size(), 1u);
  EXPECT_NE(directory[0].message.find("directory"), std::string::npos);
}

TEST(SceneLoader, SuggestsCloseNames) {
  EXPECT_EQ(closest_match("densty", {"density", "restitution"}), "density");
  EXPECT_EQ(closest_match("xyz", {"density", "restitution"}), "");
  EXPECT_EQ(closest_match("density", {"density"}), "");  // not a typo
}

// world.accuracy: a preset's name, or an object with a preset and knobs on top of it; the
// World gets exactly those knobs.
TEST(SceneLoader, AccuracyIsAPresetOrAnObjectOfKnobs) {
  const std::string bodies = R"("bodies": [{"name": "d", "shape": {"circle": {"radius": 0.2}}}])";
  const SceneLoad named = parse_scene(
      R"({"version": 1, "world": {"duration": 1, "accuracy": "draft"}, )" + bodies + "}",
      "named.json");
  ASSERT_TRUE(named.ok());
  EXPECT_EQ(named.scene.accuracy.preset, "draft");
  EXPECT_EQ(scene_accuracy(named.scene), *accuracy_preset("draft"));
  const SceneLoad object = parse_scene(
      R"({"version": 1, "world": {"duration": 1, "accuracy": {"preset": "precise",
          "max_step": 0.002, "seed_depth": 12}}, )" +
          bodies + "}",
      "object.json");
  ASSERT_TRUE(object.ok());
  Accuracy expected = *accuracy_preset("precise");
  expected.max_step = 0.002;
  expected.seed_depth = 12;
  EXPECT_EQ(scene_accuracy(object.scene), expected);
  const WorldSettings world = world_settings(object.scene);
  EXPECT_EQ(world.max_step, 0.002);
  EXPECT_EQ(world.narrow_phase.max_depth, 12);
  // Knobs alone apply to "normal".
  const SceneLoad knobs = parse_scene(
      R"({"version": 1, "world": {"duration": 1, "accuracy": {"contact_passes": 5}}, )" + bodies +
          "}",
      "knobs.json");
  ASSERT_TRUE(knobs.ok());
  EXPECT_EQ(scene_accuracy(knobs.scene).contact_passes, 5);
  EXPECT_EQ(scene_accuracy(knobs.scene).max_step, 1e-3);
}

// Every bad scene of the suite is rejected at the expected path.
TEST(SceneLoader, RejectsEveryBadSceneAtItsPath) {
  const std::filesystem::path dir = source_dir() / "tests" / "scene" / "bad";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 40u);
  for (const std::filesystem::path& file : files) {
    std::ifstream expect(std::filesystem::path(file).replace_extension(".expect"));
    std::string path, message;
    std::getline(expect, path);
    std::getline(expect, message);
    const std::vector<SceneError> errors = all_errors(file.string());
    ASSERT_FALSE(errors.empty()) << file << " was accepted";
    bool found = false;
    for (const SceneError& e : errors) {
      found = found || (e.path == path && e.message.find(message) != std::string::npos);
      EXPECT_EQ(e.file, file.string());
      if (e.path.empty()) {
        EXPECT_GT(e.line, 0) << e.describe();
      }
    }
    std::string all;
    for (const SceneError& e : errors)
      all += "\n  " + e.describe();
    EXPECT_TRUE(found) << file.filename() << ": expected " << path << " \"" << message
                       << "\", got:" << all;
  }
}

}  // namespace
}  // namespace rugosim
