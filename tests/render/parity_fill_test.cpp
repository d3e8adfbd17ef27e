// Parity fill (parity_fill.h): for random outlines, concave ones included, the parity of the
// triangles covering a point is the even-odd inside of the outline (brute force, seeded).
#include "render/draw/parity_fill.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

bool inside_even_odd(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  auto cross = [](const Vec2& o, const Vec2& u, const Vec2& v) {
    return (u.x() - o.x()) * (v.y() - o.y()) - (u.y() - o.y()) * (v.x() - o.x());
  };
  const double d1 = cross(a, b, p), d2 = cross(b, c, p), d3 = cross(c, a, p);
  const bool negative = d1 < 0 || d2 < 0 || d3 < 0;
  const bool positive = d1 > 0 || d2 > 0 || d3 > 0;
  return !(negative && positive);
}

TEST(ParityFill, CoverageParityIsTheEvenOddInside) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int shape = 0; shape < 60; ++shape) {
    // A star-like outline with random radii (often deeply concave) of 3 to 3000 points.
    const auto n = static_cast<std::size_t>(3 + std::pow(1000.0, unit(rng)) * 3);
    std::vector<Vec2> outline;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
      const double r = 0.2 + unit(rng);
      outline.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    for (const std::size_t stride : {2u, 8u, 64u}) {
      const ParityFill fill = parity_fill(outline, stride);
      ASSERT_EQ(fill.indices.size() % 3, 0u);
      std::vector<Vec2> points(outline);
      points.push_back(fill.anchor);
      for (int sample = 0; sample < 200; ++sample) {
        const Vec2 p(2.4 * unit(rng) - 1.2, 2.4 * unit(rng) - 1.2);
        bool parity = false;
        for (std::size_t t = 0; t < fill.indices.size(); t += 3) {
          if (in_triangle(p, points[fill.indices[t]], points[fill.indices[t + 1]],
                          points[fill.indices[t + 2]])) {
            parity = !parity;
          }
        }
        EXPECT_EQ(parity, inside_even_odd(outline, p)) << "n " << n << " stride " << stride;
      }
    }
  }
}

TEST(ParityFill, TrianglesStayLocalExceptTheFewOfTheCoarsestRing) {
  std::vector<Vec2> circle;
  for (int i = 0; i < 4096; ++i) {
    const double a = 2.0 * M_PI * i / 4096.0;
    circle.emplace_back(std::cos(a), std::sin(a));
  }
  const ParityFill fill = parity_fill(circle, 8);
  // 4096 → 512 → 64 → 8 points: caps of 7 triangles per ring edge, then the anchor's 8.
  EXPECT_EQ(fill.indices.size() / 3, 4096u * 7 / 8 + 512u * 7 / 8 + 64u * 7 / 8 + 8u);
}

TEST(ParityFill, TooFewPointsGiveNothing) {
  EXPECT_TRUE(parity_fill(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0)}).indices.empty());
}

}  // namespace
}  // namespace rugosim
