#include "engine/geometry/orientation.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/mass_properties.h"
#include "support/random_curves.h"

namespace rugosim {
namespace {

using testing::extent_of;
using testing::random_control_polygon;
using testing::random_segment_count;

constexpr int kCases = 300;

TEST(Orientation, ReversedSegmentTracesTheOldSegmentBackwards) {
  Rng rng(201);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const PeriodicBSpline old_curve(points);
    const Reversal r = reverse_orientation(points);
    const PeriodicBSpline new_curve(r.control_points);
    const std::size_t n = points.size();
    ASSERT_EQ(new_curve.size(), n);
    ASSERT_EQ(r.old_segment_of.size(), n);
    EXPECT_TRUE(r.reversed);
    const double scale = extent_of(points) + points.front().norm();
    for (std::size_t k = 0; k < n; k += 1 + n / 64) {
      EXPECT_EQ(r.old_segment_of[k], (n - k) % n);
      for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
        EXPECT_LE((new_curve.point(k, t) - old_curve.point((n - k) % n, 1.0 - t)).norm(),
                  1e-13 * scale)
            << "n " << n << " k " << k << " t " << t;
        // Running the other way flips the tangent.
        EXPECT_LE((new_curve.derivative(k, t) + old_curve.derivative((n - k) % n, 1.0 - t)).norm(),
                  1e-13 * scale);
      }
    }
  }
}

TEST(Orientation, ReversalFlipsTheSignOfTheArea) {
  Rng rng(202);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const PeriodicBSpline old_curve(points);
    const PeriodicBSpline new_curve(reverse_orientation(points).control_points);
    const double area = signed_area(old_curve);
    ASSERT_GT(area, 0.0);  // the generator walks around its centre counter-clockwise
    EXPECT_TRUE(is_counter_clockwise(old_curve));
    EXPECT_FALSE(is_counter_clockwise(new_curve));
    EXPECT_NEAR(signed_area(new_curve), -area, 1e-12 * area);
  }
}

TEST(Orientation, ReversingTwiceIsTheIdentity) {
  Rng rng(203);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const Reversal once = reverse_orientation(points);
    const Reversal twice = reverse_orientation(once.control_points);
    EXPECT_EQ(twice.control_points, points);  // a permutation: bitwise equal
    for (std::size_t k = 0; k < points.size(); ++k)
      EXPECT_EQ(once.old_segment_of[twice.old_segment_of[k]], k);
  }
}

TEST(Orientation, MakeCounterClockwiseReversesOnlyClockwiseCurves) {
  Rng rng(204);
  for (int c = 0; c < 100; ++c) {
    auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const Reversal kept = make_counter_clockwise(points);
    EXPECT_FALSE(kept.reversed);
    EXPECT_EQ(kept.control_points, points);
    for (std::size_t k = 0; k < points.size(); ++k)
      EXPECT_EQ(kept.old_segment_of[k], k);

    std::reverse(points.begin(), points.end());  // now clockwise
    const Reversal fixed = make_counter_clockwise(points);
    EXPECT_TRUE(fixed.reversed);
    EXPECT_TRUE(is_counter_clockwise(PeriodicBSpline(fixed.control_points)));
  }
  EXPECT_THROW(make_counter_clockwise(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}),
               std::invalid_argument);
}

TEST(Orientation, PerSegmentDataFollowsItsSegment) {
  // Tag each segment of a clockwise curve with a property of its own geometry (its midpoint,
  // standing in for σ_j); after normalisation every tag must still describe its segment.
  Rng rng(205);
  for (int c = 0; c < 100; ++c) {
    auto points = random_control_polygon(rng, random_segment_count(rng, c));
    std::reverse(points.begin(), points.end());
    const PeriodicBSpline old_curve(points);
    std::vector<Vec2> midpoints;
    for (std::size_t j = 0; j < old_curve.size(); ++j)
      midpoints.push_back(old_curve.point(j, 0.5));

    const Reversal r = make_counter_clockwise(points);
    ASSERT_TRUE(r.reversed);
    const PeriodicBSpline new_curve(r.control_points);
    const std::vector<Vec2> followed = follow_segments(r, std::span<const Vec2>(midpoints));
    ASSERT_EQ(followed.size(), new_curve.size());
    const double scale = extent_of(points) + points.front().norm();
    for (std::size_t k = 0; k < new_curve.size(); ++k)
      EXPECT_LE((followed[k] - new_curve.point(k, 0.5)).norm(), 1e-13 * scale) << k;
  }
}

}  // namespace
}  // namespace rugosim
