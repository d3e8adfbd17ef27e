// What collision needs to know of one body, in its body frame, built once: the boundary curve,
// its tolerances along the boundary, and its augmented OBB tree (paper §3.1). Nothing here
// changes while the body moves; placement comes with each query as a Transform2.
#pragma once

#include "engine/collision/aobb_tree.h"
#include "engine/core/aabb.h"
#include "engine/core/transform.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/tolerance_profile.h"

namespace rugosim {

class CollisionShape {
 public:
  // Throws std::invalid_argument when the profile's size differs from the segment count or the
  // curve runs clockwise (orientation.h's make_counter_clockwise normalises it first).
  CollisionShape(PeriodicBSpline curve, ToleranceProfile tolerances);

  const PeriodicBSpline& curve() const { return curve_; }
  const ToleranceProfile& tolerances() const { return tolerances_; }
  const AobbTree& tree() const { return tree_; }

  // World box around the placed body and its tolerance band, for the broad phase.
  Aabb world_bounds(const Transform2& placement) const;

 private:
  PeriodicBSpline curve_;
  ToleranceProfile tolerances_;
  AobbTree tree_;
};

}  // namespace rugosim
