// libFuzzer target for the scene loader: any bytes go through parse_scene and, when they make a
// valid scene of a reasonable size, through build_world, as `rugosim validate` does. Crashes,
// sanitizer reports and broken invariants abort; an exception escaping is a bug too, so none
// is caught here and libFuzzer reports it as a crash. tests/fuzz/run_fuzz.sh runs it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "support/scene_invariants.h"

namespace {

const std::string kFile = "fuzz.json";

[[noreturn]] void fail(const char* stage, const std::string& why) {
  std::fprintf(stderr, "scene_loader_fuzz: %s: %s\n", stage, why.c_str());
  std::abort();
}

void check_errors(const char* stage, const std::vector<rugosim::SceneError>& errors) {
  const std::string why = rugosim::testing::first_malformed(errors);
  if (!why.empty()) fail(stage, why);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const rugosim::SceneLoad load = rugosim::parse_scene(text, kFile);
  check_errors("parse_scene", load.errors);
  if (!load.ok()) return 0;
  // A scene without errors is complete: what the format requires is there.
  if (load.scene.bodies.empty()) fail("parse_scene", "a valid scene without bodies");
  if (!(load.scene.duration > 0.0)) fail("parse_scene", "a valid scene without a duration > 0");
  if (rugosim::testing::too_large_to_build(load.scene)) return 0;

  const rugosim::SceneWorld built = rugosim::build_world(load.scene, kFile);
  check_errors("build_world", built.errors);
  if ((built.world == nullptr) != !built.errors.empty()) {
    fail("build_world", "a World must be returned exactly when there are no errors");
  }
  if (built.world != nullptr && built.world->body_count() != load.scene.bodies.size()) {
    fail("build_world", "the World does not have one body per scene body");
  }
  return 0;
}
