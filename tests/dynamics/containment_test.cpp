// A body wholly inside another (engine/dynamics/containment.h, issue 15): found by sampled
// boundaries against brute force, and counted by the World as a crossing.
#include "engine/dynamics/containment.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/dynamics/overlap_depth.h"
#include "engine/dynamics/world.h"
#include "engine/geometry/shapes.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::make_material;

// A fixed irregular, concave body about 1 m across, turned and moved off the origin.
RigidBody concave_outer() {
  RigidBodyDesc d;
  d.control_points = blob_control_points(1.0, 0.6, 48, 7);
  d.position = Vec2(3.0, -2.0);
  d.angle = 0.7;
  d.fixed = true;
  return RigidBody(d);
}

TEST(Containment, SmallDisksInsideAndOutsideAConcaveBodyAgreeWithAFineWindingTest) {
  // Seeded: 1 cm disks anywhere in the outer body's box, kept 2 cm clear of its boundary
  // (closer, they would touch or cross it: not a containment question). The answer must
  // match the winding number of a 1,024-points-per-segment polygon at the disk's centre.
  const RigidBody outer = concave_outer();
  const ContainmentSamples outer_samples = containment_samples(outer);
  const std::vector<Vec2> fine = sampled_boundary(outer, 1024);
  Rng rng(15);
  int inside = 0, outside = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec2 c(3.0 + rng.uniform(-1.7, 1.7), -2.0 + rng.uniform(-1.7, 1.7));
    if (distance_to_polygon(fine, c) < 0.02) continue;
    const RigidBody inner = disk(0.01, 16, c, Vec2::Zero(), make_material(0.3, 0.5));
    const auto nested = lies_inside(inner, containment_samples(inner), outer, outer_samples);
    ASSERT_TRUE(nested.has_value()) << k;
    EXPECT_EQ(*nested, inside_polygon(fine, c)) << "case " << k << " at " << c.transpose();
    (*nested ? inside : outside) += 1;
  }
  EXPECT_GT(inside, 50);
  EXPECT_GT(outside, 50);
}

TEST(Containment, ABodyThatEndsUpInsideAnotherIsACrossing) {
  // A disk inside a fixed box's interior (as a fallback or a bad caller could leave it; validate
  // refuses such a scene): the boundaries never meet, yet the World must see a crossing, name
  // the pair and give a depth.
  World world;
  RigidBodyDesc block;
  block.control_points = box_control_points(2.0, 2.0, 16);
  block.fixed = true;
  world.add_body(RigidBody(block), "block");
  world.add_body(disk(0.1, 16, Vec2(0.2, 0.3), Vec2::Zero(), make_material(0.3, 0.5)), "pebble");
  world.advance_to(0.01);
  EXPECT_GE(world.stats().crossings, 1u);
  ASSERT_TRUE(world.first_crossing().has_value());
  EXPECT_EQ(world.first_crossing()->body_a, 0u);
  EXPECT_EQ(world.first_crossing()->body_b, 1u);
  EXPECT_GT(world.first_crossing()->depth, 0.5);  // the pebble is ~0.6 m from the nearest face
}

}  // namespace
}  // namespace rugosim
