#include "engine/collision/segment_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "engine/collision/bezier_bounds.h"
#include "engine/collision/segment_crossing.h"
#include "engine/core/random.h"
#include "segment_pair_cases.h"

namespace rugosim {
namespace {

using testing::PairKind;
using testing::parabola;
using testing::segment_from_bezier;
using testing::straight_polygon;

// Minimum of f over [lo, hi] by golden-section search (f unimodal there, else a local one).
double golden_minimum(const std::function<double(double)>& f, double lo, double hi,
                      int iterations) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < iterations; ++k) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = f(x2);
    }
  }
  return std::min({f1, f2, f(lo), f(hi)});
}

// Brute force, independent of the code under test: a 201 x 201 grid over [0, 1]², then for
// every grid s the best t polished by golden-section search (so the profile min_t ‖a(s) − b(t)‖
// is exact along s and a long flat valley cannot hide its bottom between grid points), then a
// nested golden-section search around the best s; and 2001 samples along each edge, polished.
double reference_distance(const CubicSegment& a, const CubicSegment& b) {
  constexpr int kGrid = 200;
  constexpr int kEdge = 2000;
  constexpr int kPolish = 50;
  constexpr double kStep = 1.0 / kGrid;
  std::vector<Vec2> pb;
  pb.reserve(kGrid + 1);
  for (int j = 0; j <= kGrid; ++j)
    pb.push_back(b.point(j * kStep));
  const auto dist = [&](double s, double t) { return (a.point(s) - b.point(t)).norm(); };
  const auto bracket = [](double centre, double half) {
    return std::pair{std::max(0.0, centre - half), std::min(1.0, centre + half)};
  };
  // Best over t in [t_lo, t_hi] for a given s.
  const auto profile = [&](double s, double t_lo, double t_hi) {
    return golden_minimum([&](double t) { return dist(s, t); }, t_lo, t_hi, kPolish);
  };
  // The profile along s, each value polished in t.
  std::vector<double> along, best_t;
  along.reserve(kGrid + 1);
  best_t.reserve(kGrid + 1);
  for (int i = 0; i <= kGrid; ++i) {
    const double s = i * kStep;
    const Vec2 p = a.point(s);
    double grid2 = std::numeric_limits<double>::infinity();
    int bj = 0;
    for (int j = 0; j <= kGrid; ++j) {
      const double d2 = (p - pb[static_cast<std::size_t>(j)]).squaredNorm();
      if (d2 < grid2) {
        grid2 = d2;
        bj = j;
      }
    }
    const auto [t_lo, t_hi] = bracket(bj * kStep, 1.5 * kStep);
    along.push_back(std::min(std::sqrt(grid2), profile(s, t_lo, t_hi)));
    best_t.push_back(bj * kStep);
  }
  // Polish the four lowest local minima of the profile (several basins: S curves, loops).
  std::vector<std::pair<double, std::size_t>> minima;
  for (std::size_t i = 0; i < along.size(); ++i) {
    const bool left = i == 0 || along[i] <= along[i - 1];
    const bool right = i + 1 == along.size() || along[i] <= along[i + 1];
    if (left && right) minima.emplace_back(along[i], i);
  }
  std::sort(minima.begin(), minima.end());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; m < std::min<std::size_t>(4, minima.size()); ++m) {
    const std::size_t i = minima[m].second;
    // As s sweeps its bracket the best t moves by up to the ratio of the speeds.
    const double s_i = static_cast<double>(i) * kStep;
    const double ratio =
        a.derivative(s_i).norm() / std::max(b.derivative(best_t[i]).norm(), 1e-300);
    const auto [s_lo, s_hi] = bracket(s_i, 1.5 * kStep);
    const auto [t_lo, t_hi] = bracket(best_t[i], (4.0 + 3.0 * std::min(ratio, 1e6)) * kStep);
    best = std::min(
        {best, minima[m].first,
         golden_minimum([&](double s) { return profile(s, t_lo, t_hi); }, s_lo, s_hi, kPolish)});
  }
  // Edges: one parameter at 0 or 1, the other sampled densely then polished.
  for (int edge = 0; edge < 4; ++edge) {
    const double fixed = (edge & 1) ? 1.0 : 0.0;
    const bool along_t = edge < 2;  // s fixed, t varies
    const auto on_edge = [&](double x) { return along_t ? dist(fixed, x) : dist(x, fixed); };
    double edge_best = std::numeric_limits<double>::infinity();
    int best_k = 0;
    for (int k = 0; k <= kEdge; ++k) {
      const double value = on_edge(k / double{kEdge});
      if (value < edge_best) {
        edge_best = value;
        best_k = k;
      }
    }
    const auto [lo, hi] = bracket(best_k / double{kEdge}, 2.0 / kEdge);
    best = std::min({best, edge_best, golden_minimum(on_edge, lo, hi, kPolish)});
  }
  return best;
}

double pair_size(const CubicSegment& a, const CubicSegment& b) {
  return std::max(a.hull_bounds().diagonal(), b.hull_bounds().diagonal());
}

double pair_magnitude(const CubicSegment& a, const CubicSegment& b) {
  double m = 0.0;
  for (const Vec2& p : a.bezier())
    m = std::max(m, p.cwiseAbs().maxCoeff());
  for (const Vec2& p : b.bezier())
    m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

// Invariants every answer keeps: finite, parameters in [0, 1], points on the curves and the
// distance theirs.
void expect_well_formed(const NearestPoints& n, const CubicSegment& a, const CubicSegment& b) {
  ASSERT_TRUE(std::isfinite(n.t_a) && std::isfinite(n.t_b) && std::isfinite(n.distance));
  ASSERT_TRUE(n.point_a.allFinite() && n.point_b.allFinite());
  EXPECT_GE(n.t_a, 0.0);
  EXPECT_LE(n.t_a, 1.0);
  EXPECT_GE(n.t_b, 0.0);
  EXPECT_LE(n.t_b, 1.0);
  EXPECT_EQ(n.point_a, a.point(n.t_a));
  EXPECT_EQ(n.point_b, b.point(n.t_b));
  EXPECT_EQ(n.distance, (n.point_a - n.point_b).norm());
}

// --- Closed-form cases: the expected answer is stated in each. ---

TEST(NearestPoints, PointToPoint) {
  // Two segments collapsed to points (3, 4) and (0, 0): distance 5.
  const Vec2 p(3.0, 4.0), q(0.0, 0.0);
  const CubicSegment a = segment_from_bezier({p, p, p, p});
  const CubicSegment b = segment_from_bezier({q, q, q, q});
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 5.0, 1e-14);
}

TEST(NearestPoints, PointToStraightSegment) {
  // Point (0.3, 2) over the constant-speed segment (0, 0)-(1, 0): foot at t = 0.3, distance 2.
  const Vec2 p(0.3, 2.0);
  const CubicSegment a = segment_from_bezier({p, p, p, p});
  const CubicSegment b = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 2.0, 1e-14);
  EXPECT_NEAR(n.t_b, 0.3, 1e-12);
  // Beyond the end: point (1.5, 0.5) is nearest the end (1, 0), distance √0.5.
  const Vec2 q(1.5, 0.5);
  const NearestPoints m = nearest_points(segment_from_bezier({q, q, q, q}), b);
  EXPECT_NEAR(m.distance, std::sqrt(0.5), 1e-14);
  EXPECT_EQ(m.t_b, 1.0);
}

TEST(NearestPoints, ParallelStraightSegmentsAtAGap) {
  // y = 0 for x in [0, 1] and y = 0.25 for x in [0.5, 1.5]: distance 0.25, attained along the
  // overlap x in [0.5, 1], so t_a − t_b = 0.5 there.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.5, 0.25}, {1.5, 0.25}));
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 0.25, 1e-14);
  EXPECT_NEAR(n.t_a - n.t_b, 0.5, 1e-9);
  EXPECT_GE(n.t_a, 0.5 - 1e-9);
  EXPECT_FALSE(find_crossing(a, b).has_value());
}

TEST(NearestPoints, EndToEndOfCollinearSegments) {
  // [0, 1] and [2, 3] on the x axis: corner minimum, t_a = 1, t_b = 0, distance 1.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({2.0, 0.0}, {3.0, 0.0}));
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 1.0, 1e-14);
  EXPECT_EQ(n.t_a, 1.0);
  EXPECT_EQ(n.t_b, 0.0);
}

TEST(NearestPoints, EdgeMinimumAtAnEndOfOneSegment) {
  // b starts at (0.3, 0.2) and climbs away from a = (0, 0)-(1, 0): its start is nearest, above
  // a(0.3): distance 0.2, t_a = 0.3, t_b = 0.
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.3, 0.2}, {0.6, 1.0}));
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 0.2, 1e-14);
  EXPECT_NEAR(n.t_a, 0.3, 1e-12);
  EXPECT_EQ(n.t_b, 0.0);
}

TEST(NearestPoints, RepeatedControlPointsGiveZeroEndTangents) {
  // Bézier (0,0),(0,0),(1,0),(1,0): the segment [0, 1] on the x axis with a' = 0 at both ends.
  // Against the point (1.2, 0.1) the nearest point is the end (1, 0): distance √0.05.
  const CubicSegment a =
      segment_from_bezier({Vec2(0.0, 0.0), Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 0.0)});
  const Vec2 q(1.2, 0.1);
  const CubicSegment b = segment_from_bezier({q, q, q, q});
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, std::sqrt(0.05), 1e-14);
  EXPECT_NEAR(n.t_a, 1.0, 1e-6);  // a' = 0 there: t is only determined to sqrt precision
  // and above its middle, (0.5, 0.3): distance 0.3 at t_a = 0.5 by symmetry.
  const Vec2 r(0.5, 0.3);
  const NearestPoints m = nearest_points(a, segment_from_bezier({r, r, r, r}));
  EXPECT_NEAR(m.distance, 0.3, 1e-14);
  EXPECT_NEAR(m.t_a, 0.5, 1e-9);
}

TEST(NearestPoints, ConvexAgainstConvexParabolas) {
  // y = 0.2 x² (a cup) and y = −0.01 − 0.5 x² (a cap below it): distance 0.01 at x = 0.
  const CubicSegment a = segment_from_bezier(parabola(2.0, 0.2, 0.4));
  BezierPolygon cap = parabola(1.0, -0.5, 0.7);
  for (Vec2& p : cap)
    p.y() -= 0.01;
  const CubicSegment b = segment_from_bezier(cap);
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 0.01, 1e-13);
  EXPECT_NEAR(n.point_a.x(), 0.0, 1e-6);
}

TEST(NearestPoints, ConcaveAgainstConvexParabolas) {
  // A narrower cup y = 0.01 + 0.5 x² resting inside y = 0.2 x²: the slab certificate cannot
  // hold (a bends towards b), so this exercises the branch and bound. Distance 0.01 at x = 0.
  const CubicSegment a = segment_from_bezier(parabola(2.0, 0.2, 0.4));
  BezierPolygon cup = parabola(1.0, 0.5, 0.7);
  for (Vec2& p : cup)
    p.y() += 0.01;
  const CubicSegment b = segment_from_bezier(cup);
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_NEAR(n.distance, 0.01, 1e-13);
  EXPECT_NEAR(n.point_b.x(), 0.0, 1e-5);
}

TEST(NearestPoints, TangentTouchingIsZero) {
  // The cup y = 0.3 x² on the line y = 0: they touch at the origin, distance 0.
  const CubicSegment a = segment_from_bezier(parabola(1.0, 0.3, 0.35));
  const CubicSegment b = segment_from_bezier(straight_polygon({-0.6, 0.0}, {0.4, 0.0}));
  const NearestPoints n = nearest_points(a, b);
  expect_well_formed(n, a, b);
  EXPECT_LE(n.distance, crossing_distance(a, b));
  EXPECT_NEAR(n.t_a, 0.35, 1e-5);
}

TEST(NearestPoints, ScalesWithTheGeometry) {
  // The edge-minimum case above, scaled by 1e-3 and 1e3 and moved far from the origin.
  for (const double scale : {1e-3, 1.0, 1e3}) {
    const Vec2 at(7.0 * scale, -3.0 * scale);
    const CubicSegment a = segment_from_bezier(straight_polygon(at, at + scale * Vec2(1.0, 0.0)));
    const CubicSegment b = segment_from_bezier(
        straight_polygon(at + scale * Vec2(0.3, 0.2), at + scale * Vec2(0.6, 1.0)));
    const NearestPoints n = nearest_points(a, b);
    expect_well_formed(n, a, b);
    EXPECT_NEAR(n.distance, 0.2 * scale, 1e-13 * scale);
  }
}

TEST(NearestPoints, AccuracyAndThresholdAreSmallAndOrdered) {
  const CubicSegment a = segment_from_bezier(straight_polygon({0.0, 0.0}, {1.0, 0.0}));
  const CubicSegment b = segment_from_bezier(straight_polygon({0.0, 1.0}, {1.0, 2.0}));
  EXPECT_GT(nearest_points_accuracy(a, b), 0.0);
  EXPECT_LT(nearest_points_accuracy(a, b), 1e-10);
  EXPECT_EQ(crossing_distance(a, b), 4.0 * nearest_points_accuracy(a, b));
}

// --- The bounds the search relies on are bounds. ---

TEST(SegmentDistanceBounds, ChordBoundAndSeparatingAxisNeverExceedTheSampledDistance) {
  Rng rng(5);
  for (int c = 0; c < 2000; ++c) {
    const auto [a, b] = testing::random_segment_pair(rng, static_cast<PairKind>(c % 7));
    // Sampled minimum over a sub-rectangle, against the bounds for that rectangle.
    const double s0 = rng.uniform(0.0, 0.5), s1 = s0 + rng.uniform(0.0, 0.5);
    const double t0 = rng.uniform(0.0, 0.5), t1 = t0 + rng.uniform(0.0, 0.5);
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 60; ++i) {
      for (int j = 0; j <= 60; ++j) {
        const double s = s0 + (s1 - s0) * i / 60.0, t = t0 + (t1 - t0) * j / 60.0;
        sampled = std::min(sampled, (a.point(s) - b.point(t)).norm());
      }
    }
    const auto piece = [](const CubicSegment& seg, double lo, double hi) {
      // Bézier polygon of seg over [lo, hi], from the power basis.
      const auto& k = seg.power();
      const double w = hi - lo;
      const Vec2 c0 = seg.point(lo), c1 = seg.derivative(lo) * w;
      const Vec2 c2 = 0.5 * seg.second_derivative(lo) * w * w;
      const Vec2 c3 = k[3] * w * w * w;
      return BezierPolygon{c0, c0 + c1 / 3.0, c0 + 2.0 * c1 / 3.0 + c2 / 3.0, c0 + c1 + c2 + c3};
    };
    const BezierPolygon pa = piece(a, s0, s1), pb = piece(b, t0, t1);
    const double scale = 1e-12 * (pair_size(a, b) + pair_magnitude(a, b));
    const double chord = closest_on_chords(pa[0], pa[3], pb[0], pb[3]).distance -
                         chord_deviation(pa) - chord_deviation(pb);
    EXPECT_LE(chord, sampled + scale);
    const Vec2 n = Vec2(rng.normal(), rng.normal()).normalized();
    EXPECT_LE(separating_axis_bound(a, b, n, s0, s1, t0, t1), sampled + scale);
  }
}

TEST(SegmentDistanceBounds, CubicMinimumMatchesDenseSampling) {
  Rng rng(6);
  for (int c = 0; c < 2000; ++c) {
    const std::array<double, 4> k{rng.normal(), rng.normal(), rng.normal(),
                                  c % 5 == 0 ? 0.0 : rng.normal()};
    const double lo = rng.uniform(-1.0, 1.0), hi = lo + rng.uniform(0.0, 2.0);
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 4000; ++i) {
      const double x = lo + (hi - lo) * i / 4000.0;
      sampled = std::min(sampled, k[0] + x * (k[1] + x * (k[2] + x * k[3])));
    }
    const double exact = cubic_minimum(k, lo, hi);
    EXPECT_LE(exact, sampled + 1e-12);
    EXPECT_GE(exact, sampled - 1e-5);  // sampling's own error, second order in 1/4000
  }
}

// --- Property test against the brute-force reference. ---

TEST(NearestPoints, MatchesDenseSearchOnRandomPairs) {
  constexpr int kPerKind = 1500;
  constexpr auto kKinds = static_cast<int>(PairKind::kCount);
  Rng rng(20240611);
  double worst = 0.0;
  int total = 0;
  for (int k = 0; k < kKinds; ++k) {
    const auto kind = static_cast<PairKind>(k);
    double kind_worst = -std::numeric_limits<double>::infinity();
    double kind_best = std::numeric_limits<double>::infinity();
    int beats_reference = 0, zero = 0;
    for (int c = 0; c < kPerKind; ++c, ++total) {
      const auto [a, b] = testing::random_segment_pair(rng, kind);
      const NearestPoints n = nearest_points(a, b);
      expect_well_formed(n, a, b);
      const double reference = reference_distance(a, b);
      // Relative to the segments' size (to the distance for two single points).
      const double size = std::max({pair_size(a, b), reference, 1e-300});
      const double slack = 1e-9 * size + 1e-14 * pair_magnitude(a, b);
      const double error = n.distance - reference;
      EXPECT_LE(error, slack) << testing::pair_kind_name(kind) << " case " << c;
      kind_worst = std::max(kind_worst, error / size);
      kind_best = std::min(kind_best, error / size);
      // Below the reference is never wrong (ours is a true pair of points) but means the brute
      // force missed the bottom; counted to show how sharp the check is.
      if (error < -slack) ++beats_reference;
      // find_crossing agrees with the distance, by the documented threshold.
      const bool touching = n.distance <= crossing_distance(a, b);
      EXPECT_EQ(find_crossing(a, b).has_value(), touching);
      zero += touching ? 1 : 0;
    }
    worst = std::max(worst, kind_worst);
    std::printf(
        "  %-16s %5d pairs, (ours - reference)/size in [%+.1e, %+.1e], %d below "
        "reference by > 1e-9, %d at distance zero\n",
        testing::pair_kind_name(kind), kPerKind, kind_best, kind_worst, beats_reference, zero);
  }
  std::printf("  all: %d pairs, worst (ours - reference)/size %+.2e\n", total, worst);
}

// A shallow search (seed_depth 8, the least a scene may ask for) still finds the nearest points
// of every kind of pair: its deepest rectangles seed full descents instead of being split.
// Expectation: within 1e-6 of the pair's size of the dense search (certification is what a
// shallow search gives up), and crossings still found.
TEST(NearestPoints, ShallowSeedSearchStaysCloseToTheDenseSearch) {
  NarrowPhaseSettings shallow;
  shallow.max_depth = 8;
  Rng rng(77);
  double worst = 0.0;
  for (int k = 0; k < static_cast<int>(PairKind::kCount); ++k) {
    const auto kind = static_cast<PairKind>(k);
    for (int c = 0; c < 300; ++c) {
      const auto [a, b] = testing::random_segment_pair(rng, kind);
      const NearestPoints n = nearest_points(a, b, shallow);
      expect_well_formed(n, a, b);
      const double reference = reference_distance(a, b);
      const double size = std::max({pair_size(a, b), reference, 1e-300});
      const double error = (n.distance - reference) / size;
      EXPECT_LE(error, 1e-6) << testing::pair_kind_name(kind) << " case " << c;
      worst = std::max(worst, error);
      if (nearest_points(a, b).distance <= crossing_distance(a, b)) {
        EXPECT_LE(n.distance, 1e-6 * size) << "a crossing lost, " << testing::pair_kind_name(kind);
      }
    }
  }
  RecordProperty("shallow_worst_relative_excess", std::to_string(worst));
}

// nearest_points_within: a value is nearest_points' own, bit for bit; nullopt only for pairs
// that the dense search shows to be farther apart than the threshold. Thresholds straddle each
// pair's distance, where a proof is hardest.
TEST(NearestPointsWithin, AgreesWithNearestPointsAndProvesOnlyTrueSeparations) {
  Rng rng(1207);
  // Pairs well apart, thresholds under half their distance: the proofs the collision layer
  // relies on (the rest of them get their exact value, which was cheaper than a proof).
  int proved_well_apart = 0, well_apart = 0;
  for (int k = 0; k < static_cast<int>(PairKind::kCount); ++k) {
    const auto kind = static_cast<PairKind>(k);
    for (int c = 0; c < 300; ++c) {
      const auto [a, b] = testing::random_segment_pair(rng, kind);
      const NearestPoints full = nearest_points(a, b);
      const double reference = reference_distance(a, b);
      const double size = std::max({pair_size(a, b), reference, 1e-300});
      const double slack = 1e-9 * size + 1e-14 * pair_magnitude(a, b);
      for (const double ratio : {0.0, 0.5, 0.9, 0.999, 1.001, 1.1, 2.0}) {
        const double threshold = ratio * reference;
        const WithinThreshold result = nearest_points_within(a, b, threshold);
        const std::optional<NearestPoints>& within = result.nearest;
        // The lower bound is one, and within the certificate's slack of a certified answer.
        EXPECT_LE(result.lower_bound, reference + slack);
        if (within && std::isfinite(result.lower_bound)) {
          EXPECT_GE(result.lower_bound, within->distance - slack);
        }
        const bool apart = ratio <= 0.5 && reference > 1e-6 * size;
        well_apart += apart ? 1 : 0;
        if (within) {
          EXPECT_EQ(within->t_a, full.t_a) << testing::pair_kind_name(kind) << " case " << c;
          EXPECT_EQ(within->t_b, full.t_b);
          EXPECT_EQ(within->distance, full.distance);
        } else {
          proved_well_apart += apart ? 1 : 0;
          EXPECT_GT(reference + slack, threshold)
              << testing::pair_kind_name(kind) << " case " << c << " ratio " << ratio;
          EXPECT_GT(result.lower_bound, threshold);
          // Touching pairs are never proved apart, whatever the threshold.
          EXPECT_GT(full.distance, crossing_distance(a, b));
        }
      }
    }
  }
  std::printf("  %d of %d pairs well apart proved farther than the threshold\n", proved_well_apart,
              well_apart);
  EXPECT_GE(proved_well_apart, well_apart / 4);
}

// An infinite threshold never proves anything: nearest_points itself.
TEST(NearestPointsWithin, InfiniteThresholdIsTheFullSearch) {
  Rng rng(99);
  for (int c = 0; c < 200; ++c) {
    const auto [a, b] = testing::random_segment_pair(rng, static_cast<PairKind>(c % 7));
    const auto within =
        nearest_points_within(a, b, std::numeric_limits<double>::infinity()).nearest;
    ASSERT_TRUE(within.has_value());
    EXPECT_EQ(within->distance, nearest_points(a, b).distance);
  }
}

}  // namespace
}  // namespace rugosim
