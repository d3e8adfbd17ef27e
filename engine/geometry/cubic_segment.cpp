#include "engine/geometry/cubic_segment.h"

namespace rugosim {

CubicSegment::CubicSegment(const Vec2& c0, const Vec2& c1, const Vec2& c2, const Vec2& c3) {
  // Rows of the paper's basis matrix (eq. 2), times 1/6, applied to [c0 c1 c2 c3].
  power_[3] = (-c0 + 3.0 * c1 - 3.0 * c2 + c3) / 6.0;
  power_[2] = (3.0 * c0 - 6.0 * c1 + 3.0 * c2) / 6.0;
  power_[1] = (-3.0 * c0 + 3.0 * c2) / 6.0;
  power_[0] = (c0 + 4.0 * c1 + c2) / 6.0;
  // Uniform B-spline to Bezier: the inner Bezier points split the middle leg c1-c2 in
  // thirds; the end points are the knot points (c_{k-1} + 4 c_k + c_{k+1}) / 6.
  bezier_[0] = power_[0];
  bezier_[1] = (2.0 * c1 + c2) / 3.0;
  bezier_[2] = (c1 + 2.0 * c2) / 3.0;
  bezier_[3] = (c1 + 4.0 * c2 + c3) / 6.0;
}

Aabb CubicSegment::hull_bounds() const {
  Aabb box;
  for (const Vec2& b : bezier_)
    box.extend(b);
  return box;
}

CubicSegment CubicSegment::transformed(const Transform2& x) const {
  CubicSegment out;
  out.power_[0] = x.apply(power_[0]);
  for (std::size_t k = 1; k < 4; ++k)
    out.power_[k] = x.rotate(power_[k]);
  for (std::size_t k = 0; k < 4; ++k)
    out.bezier_[k] = x.apply(bezier_[k]);
  return out;
}

}  // namespace rugosim
