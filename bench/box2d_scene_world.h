// The Box2D world of a rugosim scene (box2d_scene.h says what the translation does): built from
// the rugosim World of the scene, body for body. Internal to box2d_scene*.cpp; it includes
// Box2D.
#pragma once

#include <box2d/box2d.h>
#include <memory>
#include <vector>

#include "box2d_scene.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"

namespace rugosim::bench {

// Box2D mixes friction as sqrt(μa·μb); rugosim takes the rougher surface's, max(μa, μb)
// (engine/geometry/friction.h). Restitution is left to Box2D, whose max(εa, εb) is rugosim's.
class MaxFrictionListener : public b2ContactListener {
 public:
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;
};

struct Box2dSceneWorld {
  // Declared first so that it outlives the world that points at it.
  std::unique_ptr<MaxFrictionListener> listener;
  std::unique_ptr<b2World> world;
  std::vector<b2Body*> bodies;  // bodies[i] stands for the rugosim World's body i
  double scale = 1.0;           // Box2D lengths per metre
};

// `world` is the rugosim World built from `scene` (same bodies, same order), at its initial
// state. Throws std::invalid_argument for bad options or a body the translation does not
// support, naming it.
Box2dSceneWorld build_box2d_scene(const Scene& scene, const World& world,
                                  const Box2dSceneOptions& options);

}  // namespace rugosim::bench
