// rugosim's SI values as Box2D's, shared by the two Box2D translations (box2d_pile.cpp,
// box2d_scene_world.cpp). Box2D lengths are `scale` per metre (Box2D's tolerances are absolute,
// so small bodies are built larger); include only where Box2D's headers may be.
#pragma once

#include <box2d/box2d.h>

#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim::bench {

inline b2Vec2 to_box2d(const Vec2& v, double scale) {
  return b2Vec2(static_cast<float>(scale * v.x()), static_cast<float>(scale * v.y()));
}

// A body's place and motion as a Box2D body definition: the origin at the centre of mass, as
// rugosim's body frame is; static when the body is fixed.
inline b2BodyDef box2d_body_def(const RigidBody& body, double scale) {
  const BodyState& state = body.state();
  b2BodyDef def;
  def.type = body.fixed() ? b2_staticBody : b2_dynamicBody;
  def.position = to_box2d(state.position, scale);
  def.angle = static_cast<float>(state.angle);
  def.linearVelocity = to_box2d(state.velocity, scale);
  def.angularVelocity = static_cast<float>(state.angular_velocity);
  return def;
}

}  // namespace rugosim::bench
