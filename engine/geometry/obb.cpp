#include "engine/geometry/obb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rugosim {

std::array<Vec2, 4> Obb::corners() const {
  const Vec2 ex = half_extents.x() * axis_x;
  const Vec2 ey = half_extents.y() * axis_y;
  return {center - ex - ey, center + ex - ey, center + ex + ey, center - ex + ey};
}

bool Obb::contains(const Vec2& p, double slack) const {
  const Vec2 d = p - center;
  return std::abs(d.dot(axis_x)) <= half_extents.x() + slack &&
         std::abs(d.dot(axis_y)) <= half_extents.y() + slack;
}

Obb Obb::fattened(double margin) const {
  Obb out = *this;
  out.half_extents += Vec2(margin, margin);
  return out;
}

Obb Obb::transformed(const Transform2& x) const {
  Obb out;
  out.center = x.apply(center);
  out.axis_x = x.rotate(axis_x);
  out.axis_y = x.rotate(axis_y);
  out.half_extents = half_extents;
  return out;
}

PrincipalAxes principal_axes(std::span<const Vec2> points) {
  if (points.empty()) throw std::invalid_argument("principal_axes needs at least one point");
  // Two passes: moments about the mean, so that sets far from the origin keep their precision.
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points)
    mean += p;
  mean /= static_cast<double>(points.size());
  double a = 0.0, b = 0.0, c = 0.0;  // covariance [[a, b], [b, c]], up to the factor 1/count
  for (const Vec2& p : points) {
    const Vec2 d = p - mean;
    a += d.x() * d.x();
    b += d.x() * d.y();
    c += d.y() * d.y();
  }
  // Largest eigenvalue, then an eigenvector from the row of (C - l I) that is better
  // conditioned: (l - c, b) when a >= c, (b, l - a) otherwise. Both vanish only when the
  // covariance is a multiple of the identity (every direction is principal).
  const double half_gap = 0.5 * (a - c);
  const double l = 0.5 * (a + c) + std::hypot(half_gap, b);
  const Vec2 v = a >= c ? Vec2(l - c, b) : Vec2(b, l - a);
  const double norm = v.norm();
  PrincipalAxes axes;
  if (norm > 0.0 && std::isfinite(norm)) {
    axes.major = v / norm;
    axes.minor = perp(axes.major);
  }
  return axes;
}

Obb bound_along(std::span<const Vec2> points, const Vec2& axis_x) {
  if (points.empty()) throw std::invalid_argument("bound_along needs at least one point");
  const Vec2 axis_y = perp(axis_x);
  // Project relative to the first point: smaller numbers, less rounding, for sets far away.
  const Vec2 origin = points.front();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double lo_x = kInf, hi_x = -kInf, lo_y = kInf, hi_y = -kInf;
  for (const Vec2& p : points) {
    const Vec2 d = p - origin;
    const double u = d.dot(axis_x), w = d.dot(axis_y);
    lo_x = std::min(lo_x, u);
    hi_x = std::max(hi_x, u);
    lo_y = std::min(lo_y, w);
    hi_y = std::max(hi_y, w);
  }
  Obb box;
  box.axis_x = axis_x;
  box.axis_y = axis_y;
  box.center = origin + (0.5 * (lo_x + hi_x)) * axis_x + (0.5 * (lo_y + hi_y)) * axis_y;
  box.half_extents = Vec2(0.5 * (hi_x - lo_x), 0.5 * (hi_y - lo_y));
  return box;
}

Obb fit_obb(std::span<const Vec2> points) {
  return bound_along(points, principal_axes(points).major);
}

}  // namespace rugosim
