// Sleeping (sleep_tracker.h) through the World: resting islands sleep and cost nothing, moving
// bodies never sleep, a touch wakes a whole island, and islands sleep independently.
#include <cmath>
#include <cstddef>
#include <string>

#include <gtest/gtest.h>

#include "engine/dynamics/world.h"
#include "engine/geometry/shapes.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::floor_block;
using testing::make_material;
using testing::pair_state;
using testing::scientific;

constexpr double kG = 9.81;

// A disk (r = 0.2 m, σ = 1 mm on disk and floor) dropped 0.1 m onto a fixed floor rests inside
// its band, falls asleep within a second and from then on costs no steps: the World jumps to
// any later time (an idle jump) and the disk stays exactly where it slept.
TEST(Sleep, RestingDiskSleepsInsideTheBandAndThenCostsNoSteps) {
  World world;
  world.add_body(floor_block(3.0, 0.3, 0.0, make_material(0.3, 0.5), 1e-3), "floor");
  const std::size_t d = world.add_body(
      disk(0.2, 48, Vec2(0.0, 0.3), Vec2::Zero(), make_material(0.3, 0.5), 1e-3), "disk");
  double slept_at = -1.0;
  for (int frame = 1; frame <= 300 && slept_at < 0.0; ++frame) {
    world.advance_to(frame * 0.01);
    if (world.asleep(d)) slept_at = world.time();
  }
  ASSERT_GT(slept_at, 0.0) << "the disk never fell asleep in 3 s";
  const BodyState at_sleep = world.body(d).state();
  const std::uint64_t steps_at_sleep = world.stats().steps;
  world.advance_to(100.0);
  RecordProperty("slept_at_s", scientific(slept_at, 4));
  RecordProperty("steps_to_sleep", std::to_string(steps_at_sleep));
  EXPECT_EQ(world.stats().steps, steps_at_sleep);
  EXPECT_GE(world.stats().idle_jumps, 1u);
  EXPECT_EQ(world.time(), 100.0);
  EXPECT_EQ(world.body(d).state().position, at_sleep.position);
  EXPECT_EQ(world.body(d).state().velocity, Vec2::Zero());
  EXPECT_EQ(pair_state(world, 0, d), PairState::kContact);
  EXPECT_EQ(world.stats().crossings, 0u);
  EXPECT_EQ(world.stats().islands_slept, 1u);
}

// Checks fall every 0.25 s (after the first step at 1 ms). A disk thrown up at v0 = g·0.25 s
// from high above the floor is at the same height at the checks at 1 ms and 0.501 s; the check
// between, at its apex, is 0.31 m higher, so it must not sleep in flight.
TEST(Sleep, BodyInFreeFlightNeverSleeps) {
  World world;
  world.add_body(floor_block(3.0, 0.3, -50.0, make_material(0.3, 0.5)), "floor");
  const std::size_t d = world.add_body(
      disk(0.2, 32, Vec2::Zero(), Vec2(0.0, kG * 0.25), make_material(0.3, 0.5)), "disk");
  for (int frame = 1; frame <= 200; ++frame) {
    world.advance_to(frame * 0.01);
    ASSERT_FALSE(world.asleep(d)) << "asleep in flight at t = " << world.time();
  }
  EXPECT_EQ(world.stats().islands_slept, 0u);
}

// Without gravity a body drifting at 1 mm/s moves 0.25 mm per check window, within its
// tolerance (1% of 0.2 m): it sleeps, like any slow creep. At 0.1 m/s (25 mm per window) it
// never does. With sleeping disabled nothing sleeps.
TEST(Sleep, DriftSleepsOnlyBelowTheTolerance) {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  for (const double speed : {1e-3, 0.1}) {
    World world(settings);
    world.add_body(disk(0.2, 32, Vec2::Zero(), Vec2(speed, 0.0), make_material(0.3, 0.5)));
    world.advance_to(2.0);
    EXPECT_EQ(world.asleep(0), speed < 0.01) << "speed " << speed;
  }
  settings.sleep.enabled = false;
  World world(settings);
  world.add_body(disk(0.2, 32, Vec2::Zero(), Vec2(1e-3, 0.0), make_material(0.3, 0.5)));
  world.advance_to(2.0);
  EXPECT_FALSE(world.asleep(0));
  EXPECT_EQ(world.stats().idle_jumps, 0u);  // it keeps stepping (in long steps: nothing is near)
  EXPECT_GT(world.stats().steps, 0u);
}

// A movable w x h box (sharp corners, 32 segments) centred at `centre`, σ = 1 mm.
RigidBody box(double w, double h, const Vec2& centre, const Material& m) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(w, h, 32);
  desc.sigma.assign(32, 1e-3);
  desc.material = m;
  desc.position = centre;
  return RigidBody(desc);
}

// Two boxes resting side by side on the floor, 1 mm apart, form one island and sleep
// together (boxes, because disks would roll for ever). A third box dropped onto one of them
// wakes both (one island woken), and then all three settle and sleep again, with no crossing
// at any time. With the mid-step solve (soft_rest 0) and with the soft one (8 substeps, islands
// of two and up): there the two-box stack on the right rocked on its corners for ever before
// rest steps the soft solve made too fast were halved (World::rest_for_step; research §8.18).
class SleepWithRest : public ::testing::TestWithParam<int> {};

TEST_P(SleepWithRest, TouchWakesTheWholeIslandAndItSleepsAgain) {
  WorldSettings settings;
  settings.soft_rest_substeps = GetParam();
  settings.soft_rest_island = 2;
  World world(settings);
  const Material m = make_material(0.3, 0.5);
  world.add_body(floor_block(3.0, 0.3, 0.0, m, 1e-3), "floor");
  // 1 mm above the floor: bodies placed exactly touching may cross by a rounding, which the
  // World can only resolve through fallbacks.
  const std::size_t a = world.add_body(box(0.4, 0.3, Vec2(-0.2005, 0.151), m), "left");
  const std::size_t b = world.add_body(box(0.4, 0.3, Vec2(0.2005, 0.151), m), "right");
  world.advance_to(3.0);
  ASSERT_TRUE(world.asleep(a) && world.asleep(b));
  EXPECT_EQ(world.stats().islands_slept, 1u);

  const std::size_t c = world.add_body(box(0.2, 0.2, Vec2(0.25, 0.8), m), "dropped");
  bool both_woke = false;
  for (int frame = 1; frame <= 100; ++frame) {
    world.advance_to(3.0 + frame * 0.01);
    both_woke = both_woke || (!world.asleep(a) && !world.asleep(b));
  }
  EXPECT_TRUE(both_woke);
  EXPECT_GE(world.stats().islands_woken, 1u);
  world.advance_to(8.0);
  RecordProperty("islands_slept", std::to_string(world.stats().islands_slept));
  RecordProperty("islands_woken", std::to_string(world.stats().islands_woken));
  EXPECT_TRUE(world.asleep(a) && world.asleep(b) && world.asleep(c));
  EXPECT_GT(world.body(c).state().position.y(), 0.3);  // on top of the right box
  EXPECT_EQ(world.stats().crossings, 0u);
  EXPECT_EQ(world.stats().fallbacks, 0u);
  RecordProperty("soft_rest_retries", std::to_string(world.stats().soft_rest_retries));
  if (GetParam() == 0) {
    EXPECT_EQ(world.stats().soft_rest_retries, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Rests, SleepWithRest, ::testing::Values(0, 8),
                         [](const ::testing::TestParamInfo<int>& substeps) {
                           return substeps.param == 0 ? std::string("MidStep")
                                                      : std::string("Soft");
                         });

// Islands are independent: a disk resting at one end of the floor sleeps while another one
// keeps rolling (μ from σ: rolling without slipping goes on for ever on a flat floor).
TEST(Sleep, RestingIslandSleepsWhileAnotherRolls) {
  World world;
  const Material m = make_material(0.3, 0.5);
  world.add_body(floor_block(40.0, 0.3, 0.0, m, 2e-3), "floor");
  const std::size_t resting =
      world.add_body(disk(0.2, 48, Vec2(-15.0, 0.201), Vec2::Zero(), m, 2e-3), "resting");
  const std::size_t rolling =
      world.add_body(disk(0.2, 48, Vec2(-12.0, 0.201), Vec2(3.0, 0.0), m, 2e-3), "rolling");
  world.advance_to(3.0);
  EXPECT_TRUE(world.asleep(resting));
  EXPECT_FALSE(world.asleep(rolling));
  EXPECT_GT(world.body(rolling).state().velocity.x(), 1.0);
  EXPECT_EQ(world.stats().crossings, 0u);
}

// wake() lets a caller move a sleeping body: give it a velocity, wake it, and it flies.
TEST(Sleep, WakeLetsTheCallerMoveASleepingBody) {
  World world;
  const Material m = make_material(0.3, 0.5);
  world.add_body(floor_block(3.0, 0.3, 0.0, m, 1e-3), "floor");
  const std::size_t d = world.add_body(disk(0.2, 48, Vec2(0.0, 0.201), Vec2::Zero(), m, 1e-3));
  world.advance_to(2.0);
  ASSERT_TRUE(world.asleep(d));
  BodyState s = world.body(d).state();
  s.velocity = Vec2(0.0, 2.0);
  world.body(d).set_state(s);
  world.wake(d);
  world.advance_to(2.1);
  EXPECT_FALSE(world.asleep(d));
  EXPECT_GT(world.body(d).state().position.y() - s.position.y(), 0.1);
}

}  // namespace
}  // namespace rugosim
