#include "engine/geometry/subdivision.h"

#include <stdexcept>

namespace rugosim {

std::vector<Vec2> subdivide_control_points(std::span<const Vec2> coarse) {
  const std::size_t n = coarse.size();
  std::vector<Vec2> fine(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = coarse[(i + n - 1) % n];
    const Vec2& here = coarse[i];
    const Vec2& next = coarse[(i + 1) % n];
    fine[2 * i] = (prev + 6.0 * here + next) / 8.0;
    fine[2 * i + 1] = 0.5 * (here + next);
  }
  return fine;
}

PeriodicBSpline subdivide(const PeriodicBSpline& curve, int levels) {
  if (levels < 0) throw std::invalid_argument("subdivision levels must be >= 0");
  std::vector<Vec2> points = curve.control_points();
  for (int level = 0; level < levels; ++level)
    points = subdivide_control_points(points);
  return PeriodicBSpline(std::move(points));
}

}  // namespace rugosim
