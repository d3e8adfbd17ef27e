// Axis-aligned bounding box in 2D, used for conservative bounds (Bezier hulls, layouts).
#pragma once

#include <algorithm>
#include <limits>

#include "engine/core/types.h"

namespace rugosim {

struct Aabb {
  // An empty box: extending it by any point gives that point.
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x() > max.x() || min.y() > max.y(); }

  void extend(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Aabb& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  bool contains(const Vec2& p, double slack = 0.0) const {
    return p.x() >= min.x() - slack && p.x() <= max.x() + slack && p.y() >= min.y() - slack &&
           p.y() <= max.y() + slack;
  }
  bool overlaps(const Aabb& b) const {
    return min.x() <= b.max.x() && b.min.x() <= max.x() && min.y() <= b.max.y() &&
           b.min.y() <= max.y();
  }
  Vec2 extent() const { return max - min; }
  Vec2 center() const { return 0.5 * (min + max); }
  // Length of the diagonal: the natural length scale of what the box bounds.
  double diagonal() const { return empty() ? 0.0 : extent().norm(); }
};

}  // namespace rugosim
