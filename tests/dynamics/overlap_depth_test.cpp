// The sampled overlap depth of crossing reports (engine/dynamics/overlap_depth.h) against
// exact answers: boxes (sharp, so their sampled boundaries are exactly the rectangles)
// overlapping by a known amount, a disk wholly inside another, bodies apart; and the winding
// test on a polygon.
#include "engine/dynamics/overlap_depth.h"

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"
#include "support/test_bodies.h"

namespace {

using rugosim::RigidBody;
using rugosim::RigidBodyDesc;
using rugosim::Vec2;

RigidBody box(double w, double h, const Vec2& centre) {
  RigidBodyDesc desc;
  desc.control_points = rugosim::box_control_points(w, h, 32);
  desc.position = centre;
  return RigidBody(desc);
}

TEST(OverlapDepth, BoxesOverlappingByAKnownAmount) {
  for (const double overlap : {0.1, 0.01, 1e-6}) {
    const RigidBody a = box(1.0, 1.0, Vec2(0.0, 0.0));
    const RigidBody b = box(1.0, 2.0, Vec2(1.0 - overlap, 0.0));
    EXPECT_NEAR(rugosim::sampled_overlap_depth(a, b), overlap, 1e-9 + 1e-9 * overlap) << overlap;
  }
}

TEST(OverlapDepth, ApartOrTouchingFromOutsideIsZero) {
  const RigidBody a = box(1.0, 1.0, Vec2(0.0, 0.0));
  EXPECT_EQ(rugosim::sampled_overlap_depth(a, box(1.0, 1.0, Vec2(1.5, 0.0))), 0.0);
  EXPECT_EQ(rugosim::sampled_overlap_depth(a, box(1.0, 1.0, Vec2(0.0, 1.0 + 1e-9))), 0.0);
}

TEST(OverlapDepth, ADiskWhollyInsideAnotherReachesItsDeepestPoint) {
  const rugosim::Material m;
  const RigidBody outer = rugosim::testing::disk(1.0, 32, Vec2(0.0, 0.0), Vec2::Zero(), m);
  const RigidBody inner = rugosim::testing::disk(0.2, 16, Vec2(0.3, 0.0), Vec2::Zero(), m);
  // The inner disk's farthest point from the outer boundary is at x = 0.1: 0.9 from it.
  EXPECT_NEAR(rugosim::sampled_overlap_depth(outer, inner), 0.9, 2e-3);
  EXPECT_NEAR(rugosim::sampled_overlap_depth(inner, outer), 0.9, 2e-3);
}

TEST(OverlapDepth, WindingSeesInsideAndOutside) {
  // A concave L: the notch is outside.
  const std::vector<Vec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(rugosim::inside_polygon(l, Vec2(0.5, 0.5)));
  EXPECT_TRUE(rugosim::inside_polygon(l, Vec2(0.5, 1.5)));
  EXPECT_FALSE(rugosim::inside_polygon(l, Vec2(1.5, 1.5)));
  EXPECT_FALSE(rugosim::inside_polygon(l, Vec2(-0.1, 0.5)));
  EXPECT_DOUBLE_EQ(rugosim::distance_to_polygon(l, Vec2(1.5, 1.5)), 0.5);
}

}  // namespace
