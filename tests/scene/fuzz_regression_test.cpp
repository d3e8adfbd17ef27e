// Replays what the scene-loader fuzz target (tests/fuzz/) found: every *.json of
// tests/scene/fuzz_regressions/ goes through load_scene_file and, when valid, build_world, as
// the fuzz target does, in the normal suite and without clang. No exception may escape and
// every error must name the file and a JSON path or a line (support/scene_invariants.h).
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "support/scene_invariants.h"

namespace rugosim {
namespace {

std::filesystem::path regressions_dir() {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  const std::filesystem::path root = dir != nullptr ? dir : ".";
  return root / "tests" / "scene" / "fuzz_regressions";
}

// Sorted, so that a failure names the same file first on every machine.
std::vector<std::filesystem::path> regression_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(regressions_dir())) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The fuzz target's checks, as test failures rather than aborts.
void replay(const std::filesystem::path& file) {
  SCOPED_TRACE(file.string());
  try {
    const SceneLoad load = load_scene_file(file.string());
    EXPECT_EQ(testing::first_malformed(load.errors), "");
    if (!load.ok() || testing::too_large_to_build(load.scene)) return;
    const SceneWorld built = build_world(load.scene, file.string());
    EXPECT_EQ(testing::first_malformed(built.errors), "");
    EXPECT_EQ(built.world == nullptr, !built.errors.empty());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "exception escaped: " << e.what();
  } catch (...) {
    ADD_FAILURE() << "exception escaped (not a std::exception)";
  }
}

TEST(FuzzRegressions, EveryFoundInputLoadsWithoutEscapingExceptionsOrMalformedErrors) {
  // The folder always exists (its README.md says what it is); it may hold no input yet.
  ASSERT_TRUE(std::filesystem::is_directory(regressions_dir())) << regressions_dir();
  for (const std::filesystem::path& file : regression_files())
    replay(file);
}

// The first find: a material with only "restitution_max", below the default restitution. The
// message read the absent "restitution" key of a const JSON object; it now names the default.
TEST(FuzzRegressions, RestitutionMaxBelowTheDefaultRestitutionNamesTheDefault) {
  const SceneLoad load = parse_scene(R"({"world": {"duration": 1}, "bodies": [
    {"name": "disk", "shape": {"circle": {"radius": 0.25}}, "material": {"restitution_max": 0.3}}
  ]})",
                                     "scene.json");
  ASSERT_EQ(load.errors.size(), 1u);
  EXPECT_EQ(load.errors[0].path, "/bodies/0/material/restitution_max");
  EXPECT_NE(load.errors[0].message.find("the default 0.5"), std::string::npos)
      << load.errors[0].message;
}

}  // namespace
}  // namespace rugosim
