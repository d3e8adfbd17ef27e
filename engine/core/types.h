// Scalar and vector types shared by every layer, and the few 2D vector helpers that
// Eigen does not name (the scalar cross product and the perpendicular).
#pragma once

#include <Eigen/Core>

namespace rugosim {

using Vec2 = Eigen::Vector2d;  // m, unless a field says otherwise
using Mat2 = Eigen::Matrix2d;

// z component of the 3D cross product of (a, 0) and (b, 0).
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// a rotated by +90 degrees (counter-clockwise).
inline Vec2 perp(const Vec2& a) {
  return Vec2(-a.y(), a.x());
}

}  // namespace rugosim
