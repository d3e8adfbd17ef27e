// How deep two placed bodies overlap, for reports of an accepted crossing (World::
// first_crossing, the crossing warning of the commands): never used by the dynamics.
//
// Each boundary is sampled at `samples_per_segment` points per segment into a closed polygon.
// The depth is the largest distance from a sample of one boundary lying inside the other
// polygon (by winding number) to the other polygon's edges, over both directions: for two
// slightly crossing boundaries, how far one reaches into the other. It is exact for polygons
// and within the chord error of the sampling for the curves; a body wholly inside another
// gets the distance of its deepest sample from the outer boundary.
#pragma once

#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

// The body's boundary in world coordinates, `samples_per_segment` points per segment (at
// t = k / samples_per_segment), in the curve's order.
std::vector<Vec2> sampled_boundary(const RigidBody& body, int samples_per_segment);

// Winding number of the closed polygon around p is non-zero.
bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p);

// Distance from p to the closed polygon's edges, m.
double distance_to_polygon(const std::vector<Vec2>& polygon, const Vec2& p);

// m, ≥ 0; 0 when no sample of either boundary lies inside the other.
double sampled_overlap_depth(const RigidBody& a, const RigidBody& b, int samples_per_segment = 16);

}  // namespace rugosim
