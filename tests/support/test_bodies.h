// Small body builders and queries shared by the dynamics test suites.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/collision/collision_pipeline.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/dynamics/world.h"
#include "engine/geometry/shapes.h"

namespace rugosim::testing {

// A B-spline disk of the given radius (m) centred at `centre`, σ on every segment.
inline RigidBody disk(double radius, std::size_t segments, const Vec2& centre, const Vec2& velocity,
                      const Material& material, double sigma = 0.0) {
  RigidBodyDesc desc;
  desc.control_points = circle_control_points(radius, segments);
  desc.sigma.assign(segments, sigma);
  desc.material = material;
  desc.position = centre;
  desc.velocity = velocity;
  return RigidBody(desc);
}

// An irregular 24-segment blob (irregularity 0.4), σ = 0.
inline RigidBody blob(double radius, std::uint64_t seed, const Vec2& centre, const Vec2& velocity,
                      double angular_velocity, const Material& material) {
  RigidBodyDesc desc;
  desc.control_points = blob_control_points(radius, 0.4, 24, seed);
  desc.material = material;
  desc.position = centre;
  desc.velocity = velocity;
  desc.angular_velocity = angular_velocity;
  return RigidBody(desc);
}

// A fixed w x h slab whose top face lies at y = top; straight segments (a sharp box).
inline RigidBody floor_block(double width, double height, double top, const Material& material,
                             double sigma = 0.0) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(width, height, 32);
  desc.sigma.assign(32, sigma);
  desc.material = material;
  desc.fixed = true;
  desc.position = Vec2(0.0, top - 0.5 * height);
  return RigidBody(desc);
}

// Every manifold of a fresh detection on the world's current placement, sleeping bodies
// included (as if all were awake), so that a test sees every pair that crosses or touches.
inline std::vector<ContactManifold> detect_all(const World& world) {
  std::vector<PlacedShape> placed;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    placed.push_back(
        {&world.body(i).shape(), world.body(i).placement(), world.body(i).fixed(), false});
  }
  CollisionPipeline pipeline;
  return pipeline.detect(placed);
}

// The state of the pair (a, b) on the world's current placement.
inline PairState pair_state(const World& world, std::size_t a, std::size_t b) {
  for (const ContactManifold& m : detect_all(world)) {
    if (m.body_a == std::min(a, b) && m.body_b == std::max(a, b)) return m.state();
  }
  return PairState::kSeparated;
}

}  // namespace rugosim::testing
