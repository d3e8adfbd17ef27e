#include "engine/geometry/periodic_bspline.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rugosim {

CubicSegment make_segment(std::span<const Vec2> control_points, std::size_t j) {
  const std::size_t n = control_points.size();
  return CubicSegment(control_points[(j + n - 1) % n], control_points[j % n],
                      control_points[(j + 1) % n], control_points[(j + 2) % n]);
}

PeriodicBSpline::PeriodicBSpline(std::vector<Vec2> control_points)
    : control_points_(std::move(control_points)) {
  if (control_points_.size() < kMinControlPoints) {
    throw std::invalid_argument("a periodic cubic B-spline needs at least 4 control points, got " +
                                std::to_string(control_points_.size()));
  }
  for (std::size_t i = 0; i < control_points_.size(); ++i) {
    if (!control_points_[i].allFinite()) {
      throw std::invalid_argument("control point " + std::to_string(i) + " is not finite");
    }
  }
  segments_.reserve(control_points_.size());
  for (std::size_t j = 0; j < control_points_.size(); ++j) {
    segments_.push_back(make_segment(control_points_, j));
  }
}

CurveParam PeriodicBSpline::locate(double u) const {
  const double n = static_cast<double>(size());
  double wrapped = std::fmod(u, n);
  if (wrapped < 0.0) wrapped += n;
  double whole = std::floor(wrapped);
  double t = wrapped - whole;
  // fmod of a tiny negative u can round up to exactly n.
  if (whole >= n) {
    whole = 0.0;
    t = 0.0;
  }
  return {static_cast<std::size_t>(whole), t};
}

Vec2 PeriodicBSpline::point_at(double u) const {
  const CurveParam p = locate(u);
  return point(p.segment, p.t);
}

Vec2 PeriodicBSpline::derivative_at(double u) const {
  const CurveParam p = locate(u);
  return derivative(p.segment, p.t);
}

Vec2 PeriodicBSpline::second_derivative_at(double u) const {
  const CurveParam p = locate(u);
  return second_derivative(p.segment, p.t);
}

Aabb PeriodicBSpline::hull_bounds() const {
  Aabb box;
  for (const CubicSegment& s : segments_)
    box.extend(s.hull_bounds());
  return box;
}

}  // namespace rugosim
