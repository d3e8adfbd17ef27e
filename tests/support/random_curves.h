// Seeded random control polygons for property tests: hundreds of cases, n from 4 to 1024.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "engine/core/random.h"
#include "engine/core/types.h"

namespace rugosim::testing {

// A random polygon: star-shaped around a random centre, with random radii, scale and
// position, so that cases cover sizes from 1e-3 to 1e3 and offsets from the origin.
inline std::vector<Vec2> random_control_polygon(Rng& rng, std::size_t n) {
  const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
  const Vec2 centre(rng.uniform(-2.0, 2.0) * scale, rng.uniform(-2.0, 2.0) * scale);
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double radius = scale * rng.uniform(0.3, 1.0);
    points[i] = centre + radius * Vec2(std::cos(angle), std::sin(angle));
  }
  return points;
}

// Segment counts for property tests: always the extremes 4 and 1024, the rest random.
inline std::size_t random_segment_count(Rng& rng, int case_index) {
  if (case_index == 0) return 4;
  if (case_index == 1) return 1024;
  // Log-uniform between 4 and 1024 so that small curves get as many cases as large ones.
  return static_cast<std::size_t>(
      std::lround(std::exp(rng.uniform(std::log(4.0), std::log(1024.0)))));
}

// Relative tolerance scale of a polygon: its largest coordinate extent.
inline double extent_of(const std::vector<Vec2>& points) {
  Vec2 lo = points.front(), hi = points.front();
  for (const Vec2& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace rugosim::testing
