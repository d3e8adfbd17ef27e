#include "engine/geometry/orientation.h"

#include "engine/geometry/mass_properties.h"

namespace rugosim {

Reversal reverse_orientation(std::span<const Vec2> control_points) {
  const std::size_t n = control_points.size();
  Reversal r;
  r.reversed = true;
  r.control_points.reserve(n);
  r.old_segment_of.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    r.control_points.push_back(control_points[(n + 1 - k) % n]);
    r.old_segment_of.push_back((n - k) % n);
  }
  return r;
}

bool is_counter_clockwise(const PeriodicBSpline& curve) {
  return signed_area(curve) > 0.0;
}

Reversal make_counter_clockwise(std::span<const Vec2> control_points) {
  const PeriodicBSpline curve(std::vector<Vec2>(control_points.begin(), control_points.end()));
  if (signed_area(curve) < 0.0) return reverse_orientation(control_points);
  Reversal same;
  same.control_points = curve.control_points();
  same.old_segment_of.reserve(curve.size());
  for (std::size_t k = 0; k < curve.size(); ++k)
    same.old_segment_of.push_back(k);
  return same;
}

}  // namespace rugosim
