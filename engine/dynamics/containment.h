// A body wholly inside another (issue 15): their boundaries neither cross nor touch, so the
// collision layer sees nothing, yet one lies in the other's interior. validate refuses it at
// t = 0 (scene_world.cpp) and the World counts it as a crossing if a body ever ends up there.
//
// The test samples both boundaries into polygons, 16 points per segment, each with a tolerance:
// twice the largest distance of the curve from its chords (taken at the chords' middles) plus
// a rounding allowance. A point of the inner boundary farther than that tolerance from the
// outer polygon is on the same side of the outer curve as of the polygon; since the boundaries
// do not cross, that one point decides for the whole inner body.
#pragma once

#include <optional>
#include <vector>

#include "engine/core/aabb.h"
#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

// A boundary sampled for the test, in the body's own frame (rigid: made once per body).
struct ContainmentSamples {
  std::vector<Vec2> polygon;  // m, body frame
  double tolerance = 0.0;     // m: how far the curve may stray from the polygon
  Aabb box;                   // m, body frame, of the polygon
};

ContainmentSamples containment_samples(const RigidBody& body);

// Whether `inner` lies wholly inside `outer`, both as placed now, given that their boundaries
// neither cross nor touch; nullopt when no sample of the inner boundary is far enough from the
// outer one to decide (they nearly touch everywhere: then they are in contact, not nested).
std::optional<bool> lies_inside(const RigidBody& inner, const ContainmentSamples& inner_samples,
                                const RigidBody& outer, const ContainmentSamples& outer_samples);

}  // namespace rugosim
