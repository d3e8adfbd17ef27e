#include "engine/collision/segment_crossing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/aabb.h"
#include "engine/core/random.h"
#include "segment_pair_cases.h"

namespace rugosim {
namespace {

using testing::PairKind;
using testing::parabola;
using testing::segment_from_bezier;
using testing::straight_polygon;

// A returned crossing is a genuine common point: both curves pass within the threshold of it.
void expect_genuine(const Crossing& x, const CubicSegment& a, const CubicSegment& b) {
  ASSERT_TRUE(std::isfinite(x.t_a) && std::isfinite(x.t_b) && x.point.allFinite());
  EXPECT_GE(x.t_a, 0.0);
  EXPECT_LE(x.t_a, 1.0);
  EXPECT_GE(x.t_b, 0.0);
  EXPECT_LE(x.t_b, 1.0);
  EXPECT_LE((a.point(x.t_a) - b.point(x.t_b)).norm(), crossing_distance(a, b));
  EXPECT_LE((a.point(x.t_a) - x.point).norm(), crossing_distance(a, b));
}

// --- Closed-form cases: the expected answer is stated in each. ---

TEST(FindCrossing, StraightSegmentsCrossingAtAKnownPoint) {
  // (0,0)-(2,2) and (0,2)-(2,0) cross at (1, 1), halfway along both.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {2.0, 2.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.0, 2.0}, {2.0, 0.0}));
  const auto x = find_crossing(a, b);
  ASSERT_TRUE(x.has_value());
  expect_genuine(*x, a, b);
  EXPECT_NEAR(x->t_a, 0.5, 1e-12);
  EXPECT_NEAR(x->t_b, 0.5, 1e-12);
  EXPECT_NEAR((x->point - Vec2(1.0, 1.0)).norm(), 0.0, 1e-12);
}

TEST(FindCrossing, SeparatedSegmentsDoNotCross) {
  // Parallel at a gap of 1e-6: no crossing.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.2, 1e-6}, {1.2, 1e-6}));
  EXPECT_FALSE(find_crossing(a, b).has_value());
}

TEST(FindCrossing, SCurveCrossesALineThreeTimes) {
  // y(s) = 3h s(1 − s)(1 − 2s) with x(s) = s is zero at s = 0, 1/2, 1; the line y = 0 from
  // x = −0.1 to 1.1 meets it at those three places; any of them is a valid answer.
  const double h = 0.6;
  const CubicSegment a = segment_from_bezier(
      {Vec2(0.0, 0.0), Vec2(1.0 / 3.0, h), Vec2(2.0 / 3.0, -h), Vec2(1.0, 0.0)});
  const CubicSegment b = segment_from_bezier(straight_polygon({-0.1, 0.0}, {1.1, 0.0}));
  const auto x = find_crossing(a, b);
  ASSERT_TRUE(x.has_value());
  expect_genuine(*x, a, b);
  const double nearest_root =
      std::min({std::abs(x->t_a), std::abs(x->t_a - 0.5), std::abs(x->t_a - 1.0)});
  EXPECT_LT(nearest_root, 1e-9);
  // Lifted by 0.01 the line still crosses the S twice (near s = 0.5 and in the first hump).
  const CubicSegment lifted = segment_from_bezier(straight_polygon({-0.1, 0.01}, {1.1, 0.01}));
  const auto y = find_crossing(a, lifted);
  ASSERT_TRUE(y.has_value());
  expect_genuine(*y, a, lifted);
}

TEST(FindCrossing, LineAboveTheHumpOfAnSCurveDoesNotCross) {
  // The S above peaks at y = h·√3/6 ≈ 0.1732 (h = 0.6); the line y = 0.18 passes above it and
  // the trough is far below: separated, with another local minimum of the distance at the
  // trough that a local method could settle in.
  const double h = 0.6;
  const CubicSegment a = segment_from_bezier(
      {Vec2(0.0, 0.0), Vec2(1.0 / 3.0, h), Vec2(2.0 / 3.0, -h), Vec2(1.0, 0.0)});
  const CubicSegment b = segment_from_bezier(straight_polygon({-0.1, 0.18}, {1.1, 0.18}));
  EXPECT_FALSE(find_crossing(a, b).has_value());
  EXPECT_NEAR(nearest_points(a, b).distance, 0.18 - h * std::sqrt(3.0) / 6.0, 1e-12);
}

TEST(FindCrossing, TouchingAtOnePointCounts) {
  // T junction: b starts on a at (0.4, 0) and leaves upwards.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.4, 0.0}, {0.5, 1.0}));
  const auto x = find_crossing(a, b);
  ASSERT_TRUE(x.has_value());
  expect_genuine(*x, a, b);
  EXPECT_NEAR(x->t_a, 0.4, 1e-12);
  EXPECT_EQ(x->t_b, 0.0);
  // Tangent touching: the cup y = 0.3 x² on the line y = 0, at the origin.
  const CubicSegment cup = segment_from_bezier(parabola(1.0, 0.3, 0.35));
  const auto y = find_crossing(cup, a);
  ASSERT_TRUE(y.has_value());
  expect_genuine(*y, cup, a);
  // End to end: (0,0)-(1,0) and (1,0)-(2,1) share the point (1, 0).
  const CubicSegment c = segment_from_bezier(straight_polygon({1.0, 0.0}, {2.0, 1.0}));
  const auto z = find_crossing(a, c);
  ASSERT_TRUE(z.has_value());
  expect_genuine(*z, a, c);
  EXPECT_NEAR((z->point - Vec2(1.0, 0.0)).norm(), 0.0, 1e-12);
}

TEST(FindCrossing, OverlappingCollinearPiecesCount) {
  // [0, 1] and [0.6, 1.5] on one line overlap on [0.6, 1]: any point there is a crossing.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({1.5, 0.0}, {0.6, 0.0}));
  const auto x = find_crossing(a, b);
  ASSERT_TRUE(x.has_value());
  expect_genuine(*x, a, b);
  EXPECT_GE(x->point.x(), 0.6 - 1e-12);
  EXPECT_LE(x->point.x(), 1.0 + 1e-12);
  // and identical segments cross everywhere.
  const auto y = find_crossing(a, a);
  ASSERT_TRUE(y.has_value());
  expect_genuine(*y, a, a);
}

TEST(FindCrossing, DegeneratePointSegments) {
  // A point on a segment crosses it; a point off it does not; two equal points cross.
  const CubicSegment line = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 1.0}));
  const Vec2 on(0.25, 0.25), off(0.25, 0.3);
  const CubicSegment p_on = segment_from_bezier({on, on, on, on});
  const CubicSegment p_off = segment_from_bezier({off, off, off, off});
  ASSERT_TRUE(find_crossing(p_on, line).has_value());
  EXPECT_NEAR(find_crossing(p_on, line)->t_b, 0.25, 1e-12);
  EXPECT_FALSE(find_crossing(p_off, line).has_value());
  ASSERT_TRUE(find_crossing(p_on, p_on).has_value());
  EXPECT_FALSE(find_crossing(p_on, p_off).has_value());
}

TEST(FindCrossing, ThresholdSeparatesTouchingFromNearlyTouching) {
  // An upward parabola whose apex sits `gap` above the line y = 0: it crosses for gap < 0 and
  // is apart, at distance gap, for gaps well above the rounding threshold (~4e-12 of the size).
  // An exact tangent touch (gap 0 or 1e-14) is found within 1e-11; whether it counts as a
  // crossing is a matter of rounding, but find_crossing and crossing_from must agree on it.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  for (const double gap : {-1e-3, 0.0, 1e-14, 1e-9, 1e-3}) {
    BezierPolygon moved = parabola(0.5, 1.0, 0.5);
    for (Vec2& p : moved)
      p += Vec2(0.5, gap);
    const CubicSegment b = segment_from_bezier(moved);
    const NearestPoints n = nearest_points(a, b);
    const bool crosses = find_crossing(a, b).has_value();
    EXPECT_EQ(crossing_from(n, a, b).has_value(), crosses) << gap;
    if (gap < 0.0) {
      EXPECT_TRUE(crosses);
    } else if (gap < 1e-12) {
      EXPECT_LE(n.distance, 1e-11) << gap;
    } else {
      EXPECT_FALSE(crosses) << gap;
      EXPECT_NEAR(n.distance, gap, 1e-11) << gap;
    }
  }
}

// --- Property test against a fine polyline. ---

// A polyline through kSamples points of a segment, with a box tree over its edges (implicit,
// node k has children 2k+1 and 2k+2) for an all-pairs edge test that skips far pieces.
class Polyline {
 public:
  static constexpr int kSamples = 2001;  // 2000 edges

  explicit Polyline(const CubicSegment& c) {
    points_.reserve(kSamples);
    for (int i = 0; i < kSamples; ++i)
      points_.push_back(c.point(i / double{kSamples - 1}));
    boxes_.reserve(4 * kSamples);
    build(0, 0, kSamples - 1);
  }

  // Whether any edge of this polyline meets any edge of the other (touching counts).
  bool crosses(const Polyline& other) const {
    return visit(other, 0, 0, kSamples - 1, 0, 0, kSamples - 1);
  }

 private:
  static constexpr int kLeafEdges = 8;

  void build(std::size_t node, int first, int last) {  // edges first..last-1
    if (boxes_.size() <= node) {
      while (boxes_.size() <= node)
        boxes_.push_back(Aabb{});
    }
    Aabb box;
    for (int i = first; i <= last; ++i)
      box.extend(points_[static_cast<std::size_t>(i)]);
    boxes_[node] = box;
    if (last - first <= kLeafEdges) return;
    const int mid = (first + last) / 2;
    build(2 * node + 1, first, mid);
    build(2 * node + 2, mid, last);
  }

  static bool edges_meet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
    const double o1 = cross(p1 - p0, q0 - p0), o2 = cross(p1 - p0, q1 - p0);
    const double o3 = cross(q1 - q0, p0 - q0), o4 = cross(q1 - q0, p1 - q0);
    if (((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0)) || ((o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0)))
      return false;
    if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
    // Collinear: they meet if their boxes do.
    Aabb a, b;
    a.extend(p0);
    a.extend(p1);
    b.extend(q0);
    b.extend(q1);
    return a.overlaps(b);
  }

  bool visit(const Polyline& other, std::size_t na, int fa, int la, std::size_t nb, int fb,
             int lb) const {
    if (!boxes_[na].overlaps(other.boxes_[nb])) return false;
    const bool leaf_a = la - fa <= kLeafEdges, leaf_b = lb - fb <= kLeafEdges;
    if (leaf_a && leaf_b) {
      for (int i = fa; i < la; ++i) {
        for (int j = fb; j < lb; ++j) {
          const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
          if (edges_meet(points_[ui], points_[ui + 1], other.points_[uj], other.points_[uj + 1]))
            return true;
        }
      }
      return false;
    }
    if (!leaf_a && (leaf_b || la - fa >= lb - fb)) {
      const int mid = (fa + la) / 2;
      return visit(other, 2 * na + 1, fa, mid, nb, fb, lb) ||
             visit(other, 2 * na + 2, mid, la, nb, fb, lb);
    }
    const int mid = (fb + lb) / 2;
    return visit(other, na, fa, la, 2 * nb + 1, fb, mid) ||
           visit(other, na, fa, la, 2 * nb + 2, mid, lb);
  }

  std::vector<Vec2> points_;
  std::vector<Aabb> boxes_;
};

// Bound on how far the curve strays from its polyline: max|f''|·h²/8 per edge, f'' linear.
double chord_error(const CubicSegment& c) {
  const double h = 1.0 / (Polyline::kSamples - 1);
  const double f2 = std::max(c.second_derivative(0.0).norm(), c.second_derivative(1.0).norm());
  return f2 * h * h / 8.0;
}

TEST(FindCrossing, MatchesAFinePolylineOnRandomPairs) {
  constexpr int kPerKind = 1500;
  constexpr auto kKinds = static_cast<int>(PairKind::kCount);
  Rng rng(77031);
  int total_ambiguous = 0;
  for (int k = 0; k < kKinds; ++k) {
    const auto kind = static_cast<PairKind>(k);
    int crossing = 0, ambiguous = 0;
    for (int c = 0; c < kPerKind; ++c) {
      const auto [a, b] = testing::random_segment_pair(rng, kind);
      const auto ours = find_crossing(a, b);
      const bool polyline = Polyline(a).crosses(Polyline(b));
      if (ours) {
        expect_genuine(*ours, a, b);  // never a false crossing
        ++crossing;
      }
      if (ours.has_value() == polyline) continue;
      // The verdicts differ: allowed only where the curves come within the polylines' chord
      // error of touching (then the polyline cannot tell). A returned crossing is genuine by
      // the check above, so only a missed one needs the distance.
      const double band = chord_error(a) + chord_error(b);
      if (!ours) {
        const double d = nearest_points(a, b).distance;
        EXPECT_LE(d, band) << "missed crossing: " << testing::pair_kind_name(kind) << " case " << c
                           << ", distance " << d;
      }
      ++ambiguous;
    }
    total_ambiguous += ambiguous;
    std::printf("  %-16s %5d pairs, %d crossing, %d ambiguous (within chord error)\n",
                testing::pair_kind_name(kind), kPerKind, crossing, ambiguous);
  }
  std::printf("  all: %d ambiguous of %d\n", total_ambiguous, kPerKind * kKinds);
}

}  // namespace
}  // namespace rugosim
