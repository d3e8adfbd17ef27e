// From a validated Scene to a World: shapes generated, σ from the rugosity (patterns seeded from
// the scene's seed and the body's index), materials, placements and velocities; the accuracy
// preset chooses the World's step. The checks that need built bodies happen here: a boundary
// that crosses itself or encloses no area, and bodies that already cross each other at t = 0.
#pragma once

#include <memory>
#include <vector>

#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

namespace rugosim {

// The knobs of the scene's accuracy: its preset's, with its own knobs on top. Throws
// std::invalid_argument for an unknown preset or knob (which the loader rejects).
Accuracy scene_accuracy(const Scene& scene);

// The World settings of the scene: gravity, friction gain and scene_accuracy().
WorldSettings world_settings(const Scene& scene);

// The body descriptions of the scene, in order (throws std::invalid_argument from the shape
// generators only for values the loader already rejects).
std::vector<RigidBodyDesc> body_descriptions(const Scene& scene);

struct SceneWorld {
  std::unique_ptr<World> world;    // null when errors is not empty
  std::vector<SceneError> errors;  // file from `file`, paths /bodies/i/...
};

// Builds the World, with `threads` threads of collision detection (WorldSettings::threads: a
// setting of the run, not of the scene, since it never changes a result); every body that
// cannot be built and every pair crossing at t = 0 is reported.
SceneWorld build_world(const Scene& scene, const std::string& file, int threads = 1);

}  // namespace rugosim
