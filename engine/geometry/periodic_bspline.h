// Closed periodic uniform cubic B-spline curve (paper §2.1). n >= 4 control points give n
// segments; segment j uses control points c_{j-1}, c_j, c_{j+1}, c_{j+2} (indices mod n) and
// runs for t in [0, 1). A global parameter u in R (period n) names segment floor(u) mod n at
// t = u - floor(u); derivatives with respect to u equal those with respect to t.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/aabb.h"
#include "engine/core/types.h"
#include "engine/geometry/cubic_segment.h"

namespace rugosim {

// A place on the curve: segment index and the parameter inside it.
struct CurveParam {
  std::size_t segment = 0;
  double t = 0.0;  // in [0, 1)
};

class PeriodicBSpline {
 public:
  static constexpr std::size_t kMinControlPoints = 4;

  // Throws std::invalid_argument when fewer than 4 points are given or one is not finite.
  explicit PeriodicBSpline(std::vector<Vec2> control_points);

  std::size_t size() const { return control_points_.size(); }  // = number of segments
  const std::vector<Vec2>& control_points() const { return control_points_; }
  const std::vector<CubicSegment>& segments() const { return segments_; }
  const CubicSegment& segment(std::size_t j) const { return segments_[j]; }

  Vec2 point(std::size_t j, double t) const { return segments_[j].point(t); }
  Vec2 derivative(std::size_t j, double t) const { return segments_[j].derivative(t); }
  Vec2 second_derivative(std::size_t j, double t) const {
    return segments_[j].second_derivative(t);
  }

  // Segment and local parameter of a global parameter u (any real; wraps with period n).
  CurveParam locate(double u) const;
  Vec2 point_at(double u) const;
  Vec2 derivative_at(double u) const;
  Vec2 second_derivative_at(double u) const;

  // Box containing the whole curve (union of the segments' Bezier hulls).
  Aabb hull_bounds() const;

 private:
  std::vector<Vec2> control_points_;
  std::vector<CubicSegment> segments_;
};

// The four control points of segment j of a periodic curve with these control points.
CubicSegment make_segment(std::span<const Vec2> control_points, std::size_t j);

}  // namespace rugosim
