#include "engine/collision/obb_overlap.h"

#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

constexpr double kPi = std::numbers::pi;

Obb make_box(const Vec2& centre, double angle, const Vec2& half) {
  Obb box;
  box.center = centre;
  box.axis_x = Vec2(std::cos(angle), std::sin(angle));
  box.axis_y = perp(box.axis_x);
  box.half_extents = half;
  return box;
}

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, c - a);
}

// p in the closed convex quadrilateral q (counter-clockwise).
bool inside(const std::array<Vec2, 4>& q, const Vec2& p) {
  for (std::size_t i = 0; i < 4; ++i) {
    if (orient(q[i], q[(i + 1) % 4], p) < 0.0) return false;
  }
  return true;
}

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Closed segments [a, b] and [c, d] share a point.
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// Brute force without separating axes: two closed convex polygons meet exactly when a corner of
// one lies in the other or two of their edges meet. Boxes must have positive area.
bool brute_overlap(const Obb& a, const Obb& b) {
  const auto ca = a.corners(), cb = b.corners();
  for (const Vec2& p : ca) {
    if (inside(cb, p)) return true;
  }
  for (const Vec2& p : cb) {
    if (inside(ca, p)) return true;
  }
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      if (segments_meet(ca[i], ca[(i + 1) % 4], cb[j], cb[(j + 1) % 4])) return true;
    }
  }
  return false;
}

double random_angle(Rng& rng) {
  const double pick = rng.uniform();
  if (pick < 0.2) return 0.0;
  if (pick < 0.4) return kPi / 4.0;
  if (pick < 0.5) return kPi / 2.0;
  if (pick < 0.6) return -kPi / 4.0;
  return rng.uniform(-kPi, kPi);
}

Obb random_box(Rng& rng, double scale, const Vec2& centre) {
  const Vec2 half(scale * rng.uniform(0.01, 1.0), scale * rng.uniform(0.01, 1.0));
  return make_box(centre, random_angle(rng), half);
}

TEST(ObbOverlap, MatchesBruteForceOnRandomPairs) {
  Rng rng(11);
  int overlapping = 0, separated = 0;
  for (int c = 0; c < 20000; ++c) {
    const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const Vec2 origin = scale * Vec2(rng.uniform(-10, 10), rng.uniform(-10, 10));
    const Obb a = random_box(rng, scale, origin);
    const Obb b = random_box(rng, scale,
                             origin + scale * Vec2(rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5)));
    const bool expected = brute_overlap(a, b);
    ASSERT_EQ(obb_overlap(a, b), expected) << "case " << c;
    ASSERT_EQ(obb_overlap(b, a), expected) << "case " << c;
    (expected ? overlapping : separated)++;
  }
  // Both outcomes are well represented.
  EXPECT_GT(overlapping, 3000);
  EXPECT_GT(separated, 5000);
}

// Pairs pushed apart along a random direction to the distance where the brute force says they
// just touch (found by bisection), then moved in and out by a billionth of it.
TEST(ObbOverlap, NearTouchingPairs) {
  Rng rng(12);
  for (int c = 0; c < 1000; ++c) {
    const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const Obb a = random_box(rng, scale, scale * Vec2(rng.uniform(-3, 3), rng.uniform(-3, 3)));
    Obb b = random_box(rng, scale, a.center);
    const double angle = random_angle(rng) + (rng.uniform() < 0.5 ? 0.0 : kPi / 2.0);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    double lo = 0.0, hi = 10.0 * scale;
    for (int it = 0; it < 120; ++it) {  // to a relative 1e-36, far below 1e-9
      const double mid = 0.5 * (lo + hi);
      b.center = a.center + mid * dir;
      (brute_overlap(a, b) ? lo : hi) = mid;
    }
    b.center = a.center + lo * (1.0 - 1e-9) * dir;
    EXPECT_TRUE(obb_overlap(a, b)) << "case " << c;
    EXPECT_TRUE(obb_overlap(b, a)) << "case " << c;
    b.center = a.center + hi * (1.0 + 1e-9) * dir;
    EXPECT_FALSE(obb_overlap(a, b)) << "case " << c;
    EXPECT_FALSE(obb_overlap(b, a)) << "case " << c;
  }
}

// Exactly touching boxes (representable coordinates, so no rounding) count as overlapping.
TEST(ObbOverlap, TouchingCountsAsOverlap) {
  const Obb a = make_box(Vec2(0, 0), 0.0, Vec2(1, 1));
  EXPECT_TRUE(obb_overlap(a, make_box(Vec2(2, 0), 0.0, Vec2(1, 1))));    // edge to edge
  EXPECT_TRUE(obb_overlap(a, make_box(Vec2(2, 2), 0.0, Vec2(1, 1))));    // corner to corner
  EXPECT_TRUE(obb_overlap(a, make_box(Vec2(3, 0.5), 0.0, Vec2(2, 4))));  // edge to edge
  EXPECT_TRUE(obb_overlap(a, make_box(Vec2(1, 0.5), 0.0, Vec2(0, 0))));  // a point on an edge
  EXPECT_TRUE(obb_overlap(a, make_box(Vec2(1, 1), 0.0, Vec2(0, 0))));    // the corner point
  EXPECT_FALSE(obb_overlap(a, make_box(Vec2(2.0 + 1e-12, 0), 0.0, Vec2(1, 1))));
  EXPECT_FALSE(obb_overlap(a, make_box(Vec2(1.5, 1.5), 0.0, Vec2(0.25, 0.25))));
  // Degenerate boxes: two points, a point on a segment.
  const Obb point = make_box(Vec2(0.5, 0.5), 0.0, Vec2(0, 0));
  EXPECT_TRUE(obb_overlap(point, point));
  EXPECT_TRUE(obb_overlap(point, make_box(Vec2(0.5, 0), 0.0, Vec2(0, 0.5))));
  EXPECT_FALSE(obb_overlap(point, make_box(Vec2(0.5, 0), 0.0, Vec2(0, 0.25))));
}

TEST(ObbOverlap, IdenticalAndNestedBoxes) {
  Rng rng(13);
  for (int c = 0; c < 500; ++c) {
    const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const Obb a = random_box(rng, scale, scale * Vec2(rng.uniform(-3, 3), rng.uniform(-3, 3)));
    EXPECT_TRUE(obb_overlap(a, a));
    Obb inner = a;
    inner.half_extents *= rng.uniform(0.0, 1.0);
    const double angle = rng.uniform(-kPi, kPi);
    inner = make_box(a.center, angle, inner.half_extents * 0.5);  // fits in any orientation
    EXPECT_TRUE(obb_overlap(a, inner));
    EXPECT_TRUE(obb_overlap(inner, a));
  }
}

// A diamond (a square turned by 45°) whose vertex meets the right side of an axis-aligned
// square: the diagonal axes are the ones that separate when edges are not parallel.
TEST(ObbOverlap, RotatedFortyFiveDegrees) {
  const Obb square = make_box(Vec2(0, 0), 0.0, Vec2(1, 1));
  const double reach = 1.0 + std::sqrt(2.0);  // the diamond's vertex at x = 1
  for (double gap : {-1e-9, 1e-9, -0.1, 0.1}) {
    const Obb diamond = make_box(Vec2(reach + gap, 0.3), kPi / 4.0, Vec2(1, 1));
    EXPECT_EQ(obb_overlap(square, diamond), gap < 0.0) << gap;
    EXPECT_EQ(obb_overlap(diamond, square), gap < 0.0) << gap;
  }
  // Diamond beyond the square's corner, along the diagonal: corner to edge, where only a
  // diagonal axis separates (the square's axes see overlap).
  const double corner_reach = std::sqrt(2.0) + 1.0;  // the diamond's edge meets (1, 1)
  for (double gap : {-1e-9, 1e-9}) {
    const double d = (corner_reach + gap) / std::sqrt(2.0);
    const Obb diamond = make_box(Vec2(d, d), kPi / 4.0, Vec2(1, 1));
    EXPECT_EQ(obb_overlap(square, diamond), gap < 0.0) << gap;
    EXPECT_EQ(obb_overlap(square, diamond), brute_overlap(square, diamond)) << gap;
  }
}

}  // namespace
}  // namespace rugosim
