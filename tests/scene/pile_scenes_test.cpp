// scenes/pile_50.json, pile_200.json and pile_1000.json are the piles of bench_pile: each file
// is what tests/support/make_pile_scenes writes (so neither can drift from the other), and it
// builds, through the scene loader, the very bodies pile_scene() gives the benchmark.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "support/pile_scene.h"
#include "support/pile_scene_json.h"

namespace rugosim {
namespace {

std::string source_dir() {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  return dir != nullptr ? dir : ".";
}

class PileScene : public ::testing::TestWithParam<std::size_t> {};

INSTANTIATE_TEST_SUITE_P(Bodies, PileScene, ::testing::Values(50u, 200u, 1000u));

TEST_P(PileScene, FileIsTheGeneratorsAndBuildsTheBenchmarksBodies) {
  testing::PileSpec spec;
  spec.bodies = GetParam();
  const std::string name = "pile_" + std::to_string(spec.bodies);
  const std::string path = source_dir() + "/scenes/" + name + ".json";
  std::ifstream file(path, std::ios::binary);
  ASSERT_TRUE(file) << path;
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(text.str(), testing::pile_scene_json(spec, name, 5.0))
      << path << " differs from what make_pile_scenes writes: regenerate it";

  const SceneLoad load = load_scene_file(path);
  ASSERT_TRUE(load.ok());
  const SceneWorld built = build_world(load.scene, path);
  ASSERT_TRUE(built.world) << (built.errors.empty() ? "" : built.errors.front().describe());
  const std::vector<testing::PileBody> expected = testing::pile_scene(spec);
  ASSERT_EQ(built.world->body_count(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const RigidBody reference(expected[i].desc);
    const RigidBody& body = built.world->body(i);
    EXPECT_EQ(built.world->name(i), expected[i].name);
    EXPECT_EQ(body.fixed(), reference.fixed());
    EXPECT_EQ(body.state().position, reference.state().position) << expected[i].name;
    EXPECT_EQ(body.state().angle, reference.state().angle);
    EXPECT_EQ(body.state().velocity, reference.state().velocity);
    EXPECT_EQ(body.state().angular_velocity, reference.state().angular_velocity);
    EXPECT_EQ(body.mass(), reference.mass());
    EXPECT_EQ(body.material().restitution, reference.material().restitution);
    EXPECT_EQ(body.material().restitution_max, reference.material().restitution_max);
    EXPECT_EQ(body.curve().control_points(), reference.curve().control_points());
    EXPECT_EQ(body.shape().tolerances().segment_tolerances(),
              reference.shape().tolerances().segment_tolerances());
  }
}

}  // namespace
}  // namespace rugosim
