#include "engine/geometry/shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/core/random.h"

namespace rugosim {

namespace {

void require_segments(std::size_t n) {
  if (n < 4) throw std::invalid_argument("segments must be >= 4, got " + std::to_string(n));
}

void require_positive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string(what) + " must be finite and > 0, got " +
                                std::to_string(value));
  }
}

double angle_of(std::size_t i, std::size_t n) {
  return 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
}

}  // namespace

double circle_control_radius(double radius, std::size_t n) {
  const double step = 2.0 * std::numbers::pi / static_cast<double>(n);
  return radius * 6.0 / (4.0 + 2.0 * std::cos(step));
}

std::vector<Vec2> circle_control_points(double radius, std::size_t n) {
  return ellipse_control_points(radius, radius, n);
}

std::vector<Vec2> ellipse_control_points(double a, double b, std::size_t n) {
  require_segments(n);
  require_positive(a, "ellipse radius a");
  require_positive(b, "ellipse radius b");
  const double scale = circle_control_radius(1.0, n);
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = angle_of(i, n);
    points[i] = Vec2(scale * a * std::cos(angle), scale * b * std::sin(angle));
  }
  return points;
}

std::vector<Vec2> box_control_points(double width, double height, std::size_t n) {
  require_segments(n);
  require_positive(width, "box width");
  require_positive(height, "box height");
  const double hw = 0.5 * width, hh = 0.5 * height;
  const std::array<Vec2, 4> corners = {Vec2(-hw, -hh), Vec2(hw, -hh), Vec2(hw, hh), Vec2(-hw, hh)};
  const std::array<double, 4> lengths = {width, height, width, height};
  const double perimeter = 2.0 * (width + height);
  std::vector<Vec2> points;
  points.reserve(n);

  if (n < kSharpBoxMinSegments) {
    // Evenly spaced along the perimeter, starting at a corner.
    for (std::size_t i = 0; i < n; ++i) {
      double s = perimeter * static_cast<double>(i) / static_cast<double>(n);
      std::size_t edge = 0;
      while (edge < 3 && s > lengths[edge])
        s -= lengths[edge++];
      const Vec2& from = corners[edge];
      const Vec2& to = corners[(edge + 1) % 4];
      points.push_back(from + (s / lengths[edge]) * (to - from));
    }
    return points;
  }

  return polygon_control_points(corners, {}, n);
}

std::vector<Vec2> polygon_control_points(std::span<const Vec2> corners,
                                         std::span<const double> rounding, std::size_t n) {
  const std::size_t k = corners.size();
  if (k < 3) throw std::invalid_argument("a polygon needs at least 3 corners");
  if (!rounding.empty() && rounding.size() != k) {
    throw std::invalid_argument("polygon rounding: one length per corner, or none");
  }
  if (n < 3 * k) {
    throw std::invalid_argument("a polygon of " + std::to_string(k) + " corners needs at least " +
                                std::to_string(3 * k) + " segments, got " + std::to_string(n));
  }
  std::vector<double> lengths(k);
  double perimeter = 0.0;
  for (std::size_t e = 0; e < k; ++e) {
    lengths[e] = (corners[(e + 1) % k] - corners[e]).norm();
    if (!(lengths[e] > 0.0) || !std::isfinite(lengths[e])) {
      throw std::invalid_argument("polygon corners " + std::to_string(e) + " and " +
                                  std::to_string((e + 1) % k) + " coincide");
    }
    perimeter += lengths[e];
  }
  for (std::size_t c = 0; !rounding.empty() && c < k; ++c) {
    const double r = rounding[c];
    const double room = 0.5 * std::min(lengths[c], lengths[(c + k - 1) % k]);
    if (!(r >= 0.0) || r > room) {
      throw std::invalid_argument("polygon rounding of corner " + std::to_string(c) +
                                  " must be in [0, " + std::to_string(room) +
                                  "] m (half its shorter edge), got " + std::to_string(r));
    }
  }
  // Share the points left after the corners among the edges by length (largest remainder),
  // so the spacing is as even as possible and the result is deterministic.
  const std::size_t spare = n - 3 * k;
  std::vector<std::size_t> counts(k, 0);
  std::vector<double> remainders(k, 0.0);
  std::size_t assigned = 0;
  for (std::size_t e = 0; e < k; ++e) {
    const double exact = static_cast<double>(spare) * lengths[e] / perimeter;
    counts[e] = static_cast<std::size_t>(std::floor(exact));
    remainders[e] = exact - std::floor(exact);
    assigned += counts[e];
  }
  while (assigned < spare) {
    const auto best = static_cast<std::size_t>(
        std::max_element(remainders.begin(), remainders.end()) - remainders.begin());
    ++counts[best];
    remainders[best] = -1.0;
    ++assigned;
  }
  std::vector<Vec2> points;
  points.reserve(n);
  for (std::size_t e = 0; e < k; ++e) {
    const Vec2& corner = corners[e];
    const double r = rounding.empty() ? 0.0 : rounding[e];
    if (r > 0.0) {
      // Three single points, r back along the edge coming in, the corner, r along the edge
      // going out: the curve turns within about r of the corner, inside the polygon.
      const Vec2 in = (corner - corners[(e + k - 1) % k]).normalized();
      const Vec2 out = (corners[(e + 1) % k] - corner).normalized();
      points.push_back(corner - r * in);
      points.push_back(corner);
      points.push_back(corner + r * out);
    } else {
      // A triple point: the curve passes through the corner with zero tangent, sharp.
      for (int copy = 0; copy < 3; ++copy)
        points.push_back(corner);
    }
    // The edge's own points, evenly between where this corner's rounding ends and the next
    // one's begins (the whole edge between sharp corners).
    const std::size_t next = (e + 1) % k;
    const Vec2 along = (corners[next] - corner) / lengths[e];
    const Vec2 from = corner + r * along;
    const Vec2 to = corners[next] - (rounding.empty() ? 0.0 : rounding[next]) * along;
    for (std::size_t j = 1; j <= counts[e]; ++j) {
      const double f = static_cast<double>(j) / static_cast<double>(counts[e] + 1);
      points.push_back(from + f * (to - from));
    }
  }
  return points;
}

std::vector<Vec2> blob_control_points(double radius, double irregularity, std::size_t n,
                                      std::uint64_t seed) {
  require_segments(n);
  require_positive(radius, "blob radius");
  if (!(irregularity >= 0.0 && irregularity <= kMaxBlobIrregularity)) {
    throw std::invalid_argument("blob irregularity must be in [0, 0.9], got " +
                                std::to_string(irregularity));
  }
  constexpr int kLowest = 2, kHighest = 6;
  std::array<double, kHighest + 1> amplitude{};
  std::array<double, kHighest + 1> phase{};
  Rng rng(seed);
  double total = 0.0;
  for (int k = kLowest; k <= kHighest; ++k) {
    // Falling with the order so the outline is lumpy rather than spiky.
    amplitude[static_cast<std::size_t>(k)] = rng.uniform(0.2, 1.0) / k;
    phase[static_cast<std::size_t>(k)] = rng.uniform(0.0, 2.0 * std::numbers::pi);
    total += amplitude[static_cast<std::size_t>(k)];
  }
  const double scale = circle_control_radius(radius, n);
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = angle_of(i, n);
    double g = 0.0;
    for (int k = kLowest; k <= kHighest; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      g += amplitude[kk] * std::cos(k * angle + phase[kk]);
    }
    const double r = scale * (1.0 + irregularity * g / total);
    points[i] = Vec2(r * std::cos(angle), r * std::sin(angle));
  }
  return points;
}

}  // namespace rugosim
