// drop SCENE SECONDS: simulates a scene file and prints where each body ends.
#include <cstdio>
#include <cstdlib>

#include "engine/core/version.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  const rugosim::SceneLoad load = rugosim::load_scene_file(argv[1]);
  for (const rugosim::SceneError& e : load.errors)
    std::fprintf(stderr, "%s\n", e.describe().c_str());
  rugosim::SceneWorld built = rugosim::build_world(load.scene, argv[1]);
  if (!load.ok() || !built.world) return 2;
  built.world->advance_to(std::atof(argv[2]));
  std::printf("rugosim %s, t = %g s\n", rugosim::kVersion, built.world->time());
  for (std::size_t i = 0; i < built.world->body_count(); ++i) {
    const auto& p = built.world->body(i).state().position;
    std::printf("%s %.6f %.6f\n", built.world->name(i).c_str(), p.x(), p.y());
  }
}
