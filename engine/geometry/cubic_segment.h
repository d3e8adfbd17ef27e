// One segment of a periodic uniform cubic B-spline (paper §2.1, eqs. 1-2), cached in the
// two forms the rest of the engine needs: the power basis for fast evaluation of the point
// and its derivatives, and the Bezier control polygon for conservative hulls and subdivision.
#pragma once

#include <array>

#include "engine/core/aabb.h"
#include "engine/core/transform.h"
#include "engine/core/types.h"

namespace rugosim {

class CubicSegment {
 public:
  CubicSegment() = default;
  // From the four B-spline control points c_{j-1}, c_j, c_{j+1}, c_{j+2} of segment j.
  CubicSegment(const Vec2& c0, const Vec2& c1, const Vec2& c2, const Vec2& c3);

  // f(t) = a0 + a1 t + a2 t^2 + a3 t^3 for t in [0, 1].
  Vec2 point(double t) const {
    return power_[0] + t * (power_[1] + t * (power_[2] + t * power_[3]));
  }
  // f'(t), per unit of the segment parameter.
  Vec2 derivative(double t) const {
    return power_[1] + t * (2.0 * power_[2] + t * (3.0 * power_[3]));
  }
  // f''(t).
  Vec2 second_derivative(double t) const { return 2.0 * power_[2] + (6.0 * t) * power_[3]; }
  // f'''(t), constant on a cubic.
  Vec2 third_derivative() const { return 6.0 * power_[3]; }

  // Power-basis coefficients a0..a3.
  const std::array<Vec2, 4>& power() const { return power_; }
  // Bezier control points b0..b3: the segment runs from b0 to b3 inside their convex hull.
  const std::array<Vec2, 4>& bezier() const { return bezier_; }

  // Axis-aligned box of the Bezier control polygon: it contains the whole segment.
  Aabb hull_bounds() const;

  // The same segment placed by x (body frame to world): exact, since placement is affine.
  CubicSegment transformed(const Transform2& x) const;

 private:
  std::array<Vec2, 4> power_{};
  std::array<Vec2, 4> bezier_{};
};

}  // namespace rugosim
