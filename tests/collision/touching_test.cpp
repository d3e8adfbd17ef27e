// Touching or crossing (engine/collision/touching.h, issue 15): faces at distance 0 or a rounding
// across are in contact, a curve driven into another deeper than the tolerance crosses.
#include "engine/collision/touching.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/collision/body_pair_collider.h"
#include "engine/core/random.h"
#include "engine/geometry/orientation.h"
#include "engine/geometry/shapes.h"
#include "segment_pair_cases.h"

namespace rugosim {
namespace {

using testing::segment_from_bezier;
using testing::straight_polygon;

// B: a floor's top face, run right to left as on a counter-clockwise box (outward normal up).
const CubicSegment kFloorTop = segment_from_bezier(straight_polygon({1.0, 0.0}, {-1.0, 0.0}));

// A: a crate's bottom face at height y, run left to right (outward normal down).
CubicSegment crate_bottom(double y) {
  return segment_from_bezier(straight_polygon({-0.5, y}, {0.5, y}));
}

TEST(Touching, FacesAtZeroOrARoundingAcrossTouchAlongTheFloorNormal) {
  for (const double y : {0.0, -1e-15, 1e-15, -4e-13}) {
    const CubicSegment a = crate_bottom(y);
    const NearestPoints near = nearest_points(a, kFloorTop);
    ASSERT_LE(near.distance, std::max(crossing_distance(a, kFloorTop), 5e-13)) << y;
    const auto n = touching(near, a, kFloorTop, 1e-9);
    ASSERT_TRUE(n.has_value()) << y;
    EXPECT_NEAR(n->normal.x(), 0.0, 1e-12) << y;
    EXPECT_NEAR(n->normal.y(), 1.0, 1e-12) << y;  // from B (the floor) towards A (the crate)
  }
}

TEST(Touching, FacesSunkDeeperThanTheToleranceAreSeenFromInsideAndCross) {
  // A parallel face 1e-6 inside: the pair itself does not cross, but its nearest points show A
  // on B's inside, and no move by the tolerance clears it.
  const CubicSegment a = crate_bottom(-1e-6);
  const NearestPoints near = nearest_points(a, kFloorTop);
  EXPECT_NEAR(near.distance, 1e-6, 1e-12);
  EXPECT_TRUE(seen_from_inside(near, a, kFloorTop));
  EXPECT_FALSE(touching(near, a, kFloorTop, 1e-9).has_value());
  // The same gap on the outside is plainly apart.
  const CubicSegment above = crate_bottom(1e-6);
  EXPECT_FALSE(seen_from_inside(nearest_points(above, kFloorTop), above, kFloorTop));
}

TEST(Touching, TransversalCrossingsAreNeverTouching) {
  // Seeded: straight segments crossing at an interior point at angles of 1° to 179°, at sizes
  // from 1 mm to 100 m; any move by the tolerance along any normal still crosses.
  Rng rng(15);
  for (int k = 0; k < 500; ++k) {
    const double size = std::pow(10.0, rng.uniform(-3.0, 2.0));
    const double angle = rng.uniform(1.0, 179.0) * std::numbers::pi / 180.0;
    const double turn = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec2 at(rng.uniform(-size, size), rng.uniform(-size, size));
    const auto direction = [](double t) { return Vec2(std::cos(t), std::sin(t)); };
    const double sa = rng.uniform(0.2, 0.8), sb = rng.uniform(0.2, 0.8);
    const Vec2 da = size * direction(turn), db = size * direction(turn + angle);
    const CubicSegment a = segment_from_bezier(straight_polygon(at - sa * da, at + (1 - sa) * da));
    const CubicSegment b = segment_from_bezier(straight_polygon(at - sb * db, at + (1 - sb) * db));
    const NearestPoints near = nearest_points(a, b);
    ASSERT_LE(near.distance, crossing_distance(a, b)) << k;
    EXPECT_FALSE(touching(near, a, b, 1e-9 * size).has_value())
        << "case " << k << ", size " << size << ", angle " << angle;
  }
}

// --- Whole bodies: a crate on a floor. ---

CollisionShape box_shape(double w, double h) {
  const Reversal ccw = make_counter_clockwise(box_control_points(w, h, 16));
  return CollisionShape(PeriodicBSpline(ccw.control_points),
                        ToleranceProfile::from_sigma(std::vector<double>(16, 0.0), 0.9));
}

TEST(Touching, ACrateRestingExactlyOnAFloorIsInContactNotCrossing) {
  const CollisionShape floor = box_shape(4.0, 0.4);
  const CollisionShape crate = box_shape(0.4, 0.3);
  const Transform2 floor_place(0.0, Vec2(0.0, -0.2));
  BodyPairCollider collider;
  ContactManifold m;
  for (const double y : {0.15, 0.15 - 1e-15, 0.15 + 1e-15}) {
    collider.collide(crate, Transform2(0.0, Vec2(0.3, y)), floor, floor_place, m);
    ASSERT_EQ(m.state(), PairState::kContact) << y;
    for (const Contact& c : m.contacts) {
      EXPECT_EQ(c.distance, 0.0) << y;
      EXPECT_NEAR(c.normal.y(), 1.0, 1e-12) << y;  // from the floor (B) up to the crate (A)
    }
    // Both bottom corners hold the crate.
    bool left = false, right = false;
    for (const Contact& c : m.contacts) {
      left = left || std::abs(c.point.x() - 0.1) < 1e-9;
      right = right || std::abs(c.point.x() - 0.5) < 1e-9;
    }
    EXPECT_TRUE(left && right) << y;
  }
  // A micrometre into the floor is a crossing, whichever body is A.
  collider.collide(crate, Transform2(0.0, Vec2(0.3, 0.15 - 1e-6)), floor, floor_place, m);
  EXPECT_EQ(m.state(), PairState::kIntersecting);
  collider.collide(floor, floor_place, crate, Transform2(0.0, Vec2(0.3, 0.15 - 1e-6)), m);
  EXPECT_EQ(m.state(), PairState::kIntersecting);
}

TEST(Touching, ATiltedCrateStandingOnItsCornerTouchesAlongTheFloorNormal) {
  const CollisionShape floor = box_shape(4.0, 0.4);
  const CollisionShape crate = box_shape(0.4, 0.3);
  const Transform2 floor_place(0.0, Vec2(0.0, -0.2));
  // Turned by 0.3 rad, its lowest corner placed exactly on y = 0.
  const double turn = 0.3;
  const Transform2 turned(turn, Vec2::Zero());
  double lowest = 0.0;
  for (const Vec2& corner :
       {Vec2(0.2, 0.15), Vec2(-0.2, 0.15), Vec2(0.2, -0.15), Vec2(-0.2, -0.15)})
    lowest = std::min(lowest, turned.apply(corner).y());
  const Transform2 place(turn, Vec2(0.0, -lowest));
  BodyPairCollider collider;
  ContactManifold m;
  for (const bool crate_first : {true, false}) {
    if (crate_first) {
      collider.collide(crate, place, floor, floor_place, m);
    } else {
      collider.collide(floor, floor_place, crate, place, m);
    }
    ASSERT_EQ(m.state(), PairState::kContact) << crate_first;
    ASSERT_FALSE(m.contacts.empty());
    const double up = crate_first ? 1.0 : -1.0;  // the normal points from B towards A
    EXPECT_NEAR(m.contacts.front().normal.y(), up, 1e-9) << crate_first;
  }
}

TEST(Touching, AnOverlapBelowTheToleranceActsAtItsDeepestPoint) {
  // A 0.5 m disk 1e-12 m into a flat floor: the curves cross at the edges of a lens about
  // 1e-6 m either side of the lowest point; the contact acts at the lowest point, where a spin
  // would drive the overlap deeper, not at an edge of the lens.
  const Reversal ccw = make_counter_clockwise(circle_control_points(0.5, 64));
  const CollisionShape disk(PeriodicBSpline(ccw.control_points),
                            ToleranceProfile::from_sigma(std::vector<double>(64, 0.0), 0.9));
  const CollisionShape floor = box_shape(4.0, 0.4);
  BodyPairCollider collider;
  ContactManifold m;
  // The lowest point of the curve is a knot at angle −π/2 (radius exactly 0.5 there).
  const double x = 0.123;
  collider.collide(disk, Transform2(0.0, Vec2(x, 0.5 - 1e-12)), floor,
                   Transform2(0.0, Vec2(0.0, -0.2)), m);
  ASSERT_EQ(m.state(), PairState::kContact);
  ASSERT_EQ(m.contacts.size(), 1u);
  EXPECT_NEAR(m.contacts.front().point.x(), x, 1e-8);
  EXPECT_NEAR(m.contacts.front().normal.y(), 1.0, 1e-12);
}

// Stress seed 1076: a rock's gently curved underside 2e-8 m inside a box's face, a crossing
// closer to parallel than the seeds of draft resolve, so that the search returned the dip's
// bottom as the nearest points. dipped_inside reads it as inside at any depth; the same gap
// outside, or nearest points at a segment's end (a corner, where d need not be parallel to a
// normal), never.
TEST(Touching, ANearestPointDippedInsideAFaceIsACrossingAtAnyDepth) {
  const auto underside = [](double y) {
    BezierPolygon p = testing::parabola(0.2, 1.0, 0.5);  // apex at parameter 0.5
    for (Vec2& v : p)
      v += Vec2(0.1, y);
    return segment_from_bezier(p);
  };
  const auto near_at_apex = [](const CubicSegment& a, double t_b) {
    NearestPoints near;
    near.t_a = 0.5;
    near.point_a = a.point(0.5);
    near.t_b = t_b;
    near.point_b = kFloorTop.point(t_b);
    near.distance = (near.point_a - near.point_b).norm();
    return near;
  };
  for (const double depth : {2e-8, 1e-5, 1e-3}) {
    const CubicSegment inside = underside(-depth);
    const NearestPoints near = near_at_apex(inside, 0.45);  // the floor's point under x = 0.1
    ASSERT_NEAR(near.point_b.x(), 0.1, 1e-12);
    EXPECT_TRUE(dipped_inside(near, inside, kFloorTop)) << depth;
    // The same pair seen with B as the rock: B's point inside A.
    NearestPoints swapped = near;
    std::swap(swapped.t_a, swapped.t_b);
    std::swap(swapped.point_a, swapped.point_b);
    EXPECT_TRUE(dipped_inside(swapped, kFloorTop, inside)) << depth;
    // The touch test then finds no move by the tolerance that clears it.
    EXPECT_FALSE(touching(near, inside, kFloorTop, 1e-9).has_value()) << depth;

    const CubicSegment outside = underside(depth);
    EXPECT_FALSE(dipped_inside(near_at_apex(outside, 0.45), outside, kFloorTop)) << depth;
    // At the floor segment's end the vector need not be parallel to its normal: no verdict.
    EXPECT_FALSE(dipped_inside(near_at_apex(inside, 0.0), inside, kFloorTop)) << depth;
  }
}

}  // namespace
}  // namespace rugosim
