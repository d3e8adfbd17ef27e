// A pile of irregular bodies (tests/support/pile_scene.h, also the pile benchmark's scene)
// dropped into an open box settles and sleeps, and no two boundaries ever cross.
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "engine/dynamics/world.h"
#include "support/pile_scene.h"
#include "support/rest_creep.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::detect_all;
using testing::PileSpec;
using testing::scientific;

// 24 blobs (24 segments, σ = 3 mm: μ = 0.27, band 5.4 mm) in 5 columns, dropped from up to
// 1.6 m. Measured (release, the World's defaults): all asleep at 2.1 s after 894 steps.
TEST(Pile, TwentyFourIrregularBodiesSettleAndSleepWithoutCrossing) {
  PileSpec spec;
  spec.bodies = 24;
  World world;
  const std::vector<testing::PileBody> scene = testing::pile_scene(spec);
  for (const testing::PileBody& b : scene)
    world.add_body(RigidBody(b.desc), b.name);
  const std::size_t first = 3;  // the box's floor and walls come first

  double all_asleep_at = -1.0;
  for (int frame = 1; frame <= 80 && all_asleep_at < 0.0; ++frame) {
    world.advance_to(frame * 0.1);
    bool all = true;
    for (std::size_t i = first; i < world.body_count(); ++i)
      all = all && world.asleep(i);
    if (all) all_asleep_at = world.time();
  }
  const StepStats& stats = world.stats();
  RecordProperty("all_asleep_at_s", scientific(all_asleep_at, 3));
  RecordProperty("steps", std::to_string(stats.steps));
  RecordProperty("collisions", std::to_string(stats.collisions));
  RecordProperty("contacts", std::to_string(stats.contacts));
  RecordProperty("rigid_clusters", std::to_string(stats.rigid_clusters));
  RecordProperty("fallbacks", std::to_string(stats.fallbacks));
  ASSERT_GT(all_asleep_at, 0.0) << "not every body slept within 8 s";
  EXPECT_EQ(stats.crossings, 0u);
  EXPECT_EQ(stats.min_step_fallbacks, 0u);
  EXPECT_EQ(stats.crossing_fallbacks, 0u);
  EXPECT_EQ(stats.unresolved_states, 0u);

  // The settled state: nothing crosses, every body lies inside the box, low in it.
  for (const ContactManifold& m : detect_all(world)) {
    EXPECT_NE(m.state(), PairState::kIntersecting) << m.body_a << " x " << m.body_b;
  }
  const double half_width = 0.5 * testing::pile_box_width(spec);
  for (std::size_t i = first; i < world.body_count(); ++i) {
    const Vec2 p = world.body(i).state().position;
    EXPECT_LT(std::abs(p.x()), half_width) << world.name(i);
    EXPECT_GT(p.y(), 0.0) << world.name(i);
    EXPECT_EQ(world.body(i).state().velocity, Vec2::Zero());
  }
  // Asleep, the pile costs no more steps.
  const std::uint64_t steps = stats.steps;
  world.advance_to(60.0);
  EXPECT_EQ(world.stats().steps, steps);
}

// Resting bodies do not creep before they sleep (issue 14): over its last second awake, no body
// of the bench's 50-body pile that rested through that second (touching the same bodies at
// every frame) moves further than its contact band. With the World's defaults (the normal
// preset: mid-step rest and rest steps). Under micro-collisions alone a body resting on a slope
// creeps ½·g·sinθ·h per step. Measured: 50 bodies asleep at 1.8 s; see RecordProperty.
TEST(Pile, RestingBodiesMoveLessThanTheirBandOverTheirLastSecondAwake) {
  PileSpec spec;
  spec.bodies = 50;
  World world;
  for (const testing::PileBody& b : testing::pile_scene(spec))
    world.add_body(RigidBody(b.desc), b.name);
  testing::RestCreepTracker tracker(30);
  for (int frame = 1; frame <= 150; ++frame) {
    world.advance_to(frame / 30.0);
    tracker.record(world);
  }
  const testing::RestCreep creep = tracker.result();
  RecordProperty("resting_bodies", std::to_string(creep.resting));
  RecordProperty("worst_displacement_in_bands", scientific(creep.worst_ratio, 3));
  RecordProperty("worst_displacement_m", scientific(creep.worst_displacement, 3));
  EXPECT_GE(creep.resting, 10u) << "too few bodies rested through their last second to judge";
  EXPECT_EQ(creep.over_band, 0u) << world.name(creep.worst_body) << " moved "
                                 << creep.worst_displacement << " m, " << creep.worst_ratio
                                 << " bands";
  EXPECT_EQ(world.stats().crossings, 0u);
}

// The same pile twice gives bit-identical states: sleeping, islands and rigid clusters keep
// the World deterministic.
TEST(Pile, IsDeterministic) {
  PileSpec spec;
  spec.bodies = 12;
  auto run = [&]() {
    World world;
    for (const testing::PileBody& b : testing::pile_scene(spec))
      world.add_body(RigidBody(b.desc), b.name);
    world.advance_to(1.5);
    std::vector<BodyState> states;
    for (std::size_t i = 0; i < world.body_count(); ++i)
      states.push_back(world.body(i).state());
    return states;
  };
  const std::vector<BodyState> first = run();
  const std::vector<BodyState> second = run();
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].position, second[i].position);
    EXPECT_EQ(first[i].angle, second[i].angle);
    EXPECT_EQ(first[i].velocity, second[i].velocity);
    EXPECT_EQ(first[i].angular_velocity, second[i].angular_velocity);
  }
}

// Threads never change a result: the same pile with 1, 2, 3 and 8 threads of collision detection
// gives bit-identical states, the same events in the same order, and the same statistics; with
// resting contact by micro-collisions alone and with mid-step rest (the World's defaults and
// every preset's).
class PileThreads : public ::testing::TestWithParam<bool> {};

INSTANTIATE_TEST_SUITE_P(Rest, PileThreads, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& mid_step) {
                           return mid_step.param ? "MidStepRest" : "MicroCollisions";
                         });

TEST_P(PileThreads, ChangeNothing) {
  PileSpec spec;
  spec.bodies = 30;
  struct Run {
    std::vector<BodyState> states;
    std::vector<ContactEvent> events;
    StepStats stats;
  };
  auto run = [&](int threads) {
    WorldSettings settings;
    settings.threads = threads;
    settings.mid_step_rest = GetParam();
    World world(settings);
    for (const testing::PileBody& b : testing::pile_scene(spec))
      world.add_body(RigidBody(b.desc), b.name);
    Run out;
    for (int frame = 1; frame <= 30; ++frame) {
      world.advance_to(frame * 0.05);
      out.events.insert(out.events.end(), world.events().begin(), world.events().end());
      world.clear_events();
    }
    for (std::size_t i = 0; i < world.body_count(); ++i)
      out.states.push_back(world.body(i).state());
    out.stats = world.stats();
    return out;
  };
  const Run one = run(1);
  ASSERT_GT(one.events.size(), 1000u);
  for (const int threads : {2, 3, 8}) {
    const Run many = run(threads);
    ASSERT_EQ(many.states.size(), one.states.size());
    for (std::size_t i = 0; i < one.states.size(); ++i) {
      EXPECT_EQ(many.states[i].position, one.states[i].position) << threads << " threads";
      EXPECT_EQ(many.states[i].angle, one.states[i].angle);
      EXPECT_EQ(many.states[i].velocity, one.states[i].velocity);
      EXPECT_EQ(many.states[i].angular_velocity, one.states[i].angular_velocity);
    }
    ASSERT_EQ(many.events.size(), one.events.size()) << threads << " threads";
    for (std::size_t e = 0; e < one.events.size(); ++e) {
      EXPECT_EQ(many.events[e].time, one.events[e].time);
      EXPECT_EQ(many.events[e].body_a, one.events[e].body_a);
      EXPECT_EQ(many.events[e].body_b, one.events[e].body_b);
      EXPECT_EQ(many.events[e].point, one.events[e].point);
      EXPECT_EQ(many.events[e].jn, one.events[e].jn);
      EXPECT_EQ(many.events[e].jt, one.events[e].jt);
    }
    EXPECT_EQ(many.stats.steps, one.stats.steps);
    EXPECT_EQ(many.stats.bisections, one.stats.bisections);
    EXPECT_EQ(many.stats.contacts, one.stats.contacts);
    EXPECT_EQ(many.stats.passes, one.stats.passes);
    EXPECT_EQ(many.stats.islands_slept, one.stats.islands_slept);
    EXPECT_EQ(many.stats.rest_contacts, one.stats.rest_contacts);
    EXPECT_EQ(many.stats.rest_sweeps, one.stats.rest_sweeps);
    EXPECT_EQ(many.stats.rest_unconverged, one.stats.rest_unconverged);
    EXPECT_EQ(many.stats.rest_withdrawn, one.stats.rest_withdrawn);
    EXPECT_EQ(many.stats.rigid_clusters, one.stats.rigid_clusters);
    EXPECT_EQ(many.stats.crossings, one.stats.crossings);
  }
  if (GetParam()) {
    EXPECT_GT(one.stats.rest_contacts, 0u);
  }
}

}  // namespace
}  // namespace rugosim
