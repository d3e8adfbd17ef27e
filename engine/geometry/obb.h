// Oriented bounding boxes in the plane: the boxes of the AOBB tree (paper §3.1). A box is
// fitted to sample points by their principal axes (the eigenvectors of the 2x2 covariance)
// and sized by projecting whatever must surely lie inside it onto those axes.
#pragma once

#include <array>
#include <span>

#include "engine/core/transform.h"
#include "engine/core/types.h"

namespace rugosim {

struct Obb {
  Vec2 center = Vec2::Zero();        // m
  Vec2 axis_x = Vec2::UnitX();       // unit: the first axis (the major one, for fitted boxes)
  Vec2 axis_y = Vec2::UnitY();       // unit: perp(axis_x), so the frame is right-handed
  Vec2 half_extents = Vec2::Zero();  // m, half widths along axis_x and axis_y, >= 0

  // center ± hx·axis_x ± hy·axis_y, counter-clockwise from (-hx, -hy).
  std::array<Vec2, 4> corners() const;

  // Whether p lies in the box grown by `slack` (m) along both axes.
  bool contains(const Vec2& p, double slack = 0.0) const;

  // The box grown by `margin` (m, >= 0) on every side: it then contains every point within
  // `margin` of the original box (the tolerance band of what it bounds).
  Obb fattened(double margin) const;

  // The same box placed by x (exact up to rounding: placement is rigid).
  Obb transformed(const Transform2& x) const;

  double area() const { return 4.0 * half_extents.x() * half_extents.y(); }  // m²
};

// Unit eigenvectors of a point set's covariance: `major` along the largest spread, `minor` =
// perp(major).
struct PrincipalAxes {
  Vec2 major = Vec2::UnitX();
  Vec2 minor = Vec2::UnitY();
};

// Principal axes of the points (closed form for the symmetric 2x2 eigenproblem). Degenerate
// sets still get a valid frame: all points equal, or a spread equal in every direction, give
// the x and y axes; collinear points give the line's direction. Throws std::invalid_argument
// for an empty set.
PrincipalAxes principal_axes(std::span<const Vec2> points);

// The smallest box with axes (axis_x, perp(axis_x)) that contains the points; axis_x must be a
// unit vector. Throws std::invalid_argument for an empty set.
Obb bound_along(std::span<const Vec2> points, const Vec2& axis_x);

// bound_along(points, principal_axes(points).major).
Obb fit_obb(std::span<const Vec2> points);

}  // namespace rugosim
