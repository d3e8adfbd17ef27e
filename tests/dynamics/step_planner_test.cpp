#include "engine/dynamics/step_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/dynamics/free_flight.h"
#include "engine/dynamics/world.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

const Vec2 kGravity(0.0, -9.81);

// A crowd of rough blobs (and a few fixed ones) at random places, with random velocities and
// spins up to `speed` (m/s); movers marked in `moves`.
std::vector<RigidBody> random_crowd(Rng& rng, std::size_t n, double speed,
                                    std::vector<std::uint8_t>& moves) {
  std::vector<RigidBody> bodies;
  moves.clear();
  for (std::size_t i = 0; i < n; ++i) {
    RigidBodyDesc desc;
    desc.control_points = blob_control_points(rng.uniform(0.02, 0.2), 0.4, 24, rng.next_u64());
    desc.sigma.assign(24, 0.002);
    desc.fixed = rng.uniform() < 0.15;
    desc.position = Vec2(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
    desc.angle = rng.uniform(0.0, 6.3);
    if (!desc.fixed) {
      desc.velocity = speed * Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
      desc.angular_velocity = rng.uniform(-speed, speed) * 10.0;
    }
    bodies.emplace_back(desc);
    moves.push_back(!desc.fixed && rng.uniform() < 0.9 ? 1 : 0);  // some movers asleep
  }
  return bodies;
}

// The longest step, at most h, in which every pair moves relative to each other at most
// limit(i, j), computed as before the sweep: every pair tested.
template <typename Limit>
double all_pairs_longest_step(const std::vector<RigidBody>& bodies,
                              const std::vector<std::uint8_t>& moves, double h,
                              const Limit& limit) {
  const double g = kGravity.norm();
  double safe = h;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (moves[i] == 0) continue;
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      if (j == i || (moves[j] != 0 && j < i)) continue;
      const bool j_moves = moves[j] != 0;
      const BodyState& si = bodies[i].state();
      const BodyState& sj = bodies[j].state();
      const double a = j_moves ? (si.velocity - sj.velocity).norm() +
                                     std::abs(si.angular_velocity) * bodies[i].bounding_radius() +
                                     std::abs(sj.angular_velocity) * bodies[j].bounding_radius()
                               : bodies[i].boundary_speed();
      const double b = j_moves ? 0.0 : 0.5 * g;
      const double reach = a * h + b * h * h;
      const double most = limit(i, j);
      if (reach <= most) continue;
      Aabb grown = bodies[i].shape().world_bounds(bodies[i].placement());
      grown.min -= Vec2::Constant(reach);
      grown.max += Vec2::Constant(reach);
      if (!grown.overlaps(bodies[j].shape().world_bounds(bodies[j].placement()))) continue;
      const double dt = b > 0.0 ? 2.0 * most / (a + std::sqrt(a * a + 4.0 * b * most)) : most / a;
      safe = std::min(safe, dt);
    }
  }
  return safe;
}

// The tunnelling bound as it was computed before the sweep: every pair tested.
double all_pairs_tunnel_free(const std::vector<RigidBody>& bodies,
                             const std::vector<std::uint8_t>& moves, double h, double min_step) {
  const double g = kGravity.norm();
  double thinnest = std::numeric_limits<double>::infinity();
  double fastest = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    thinnest = std::min(thinnest, bodies[i].thickness());
    if (moves[i] != 0) fastest = std::max(fastest, bodies[i].boundary_speed());
  }
  if (2.0 * (fastest * h + 0.5 * g * h * h) <= 0.5 * thinnest) return h;
  const double safe = all_pairs_longest_step(bodies, moves, h, [&](std::size_t i, std::size_t j) {
    return 0.5 * std::min(bodies[i].thickness(), bodies[j].thickness());
  });
  return std::min(h, std::max(safe, min_step));
}

// The sweep finds every pair the all-pairs test does: the same bound, bit for bit.
TEST(StepPlanner, TunnelFreeStepEqualsTheAllPairsBound) {
  Rng rng(8);
  StepPlanner planner;
  int cut = 0;
  for (int c = 0; c < 200; ++c) {
    std::vector<std::uint8_t> moves;
    const std::vector<RigidBody> bodies =
        random_crowd(rng, 5 + static_cast<std::size_t>(rng.uniform(0.0, 60.0)),
                     std::pow(10.0, rng.uniform(-1.0, 2.0)), moves);
    const double h = std::pow(10.0, rng.uniform(-4.0, -1.5));
    const double expected = all_pairs_tunnel_free(bodies, moves, h, 1e-9);
    EXPECT_EQ(planner.tunnel_free(bodies, moves, kGravity, h, 1e-9), expected) << "case " << c;
    cut += expected < h ? 1 : 0;
  }
  EXPECT_GT(cut, 50);  // the cases do cut steps
}

// The gentle step (rest steps, WorldSettings::rest_stride) finds every pair the all-pairs test
// does too: the same step, bit for bit, for crowds from resting to fast.
TEST(StepPlanner, GentleStepEqualsTheAllPairsBandBound) {
  Rng rng(81);
  StepPlanner planner;
  int cut = 0, whole = 0;
  for (int c = 0; c < 200; ++c) {
    std::vector<std::uint8_t> moves;
    const std::vector<RigidBody> bodies =
        random_crowd(rng, 5 + static_cast<std::size_t>(rng.uniform(0.0, 60.0)),
                     std::pow(10.0, rng.uniform(-4.0, 0.0)), moves);
    const double h = std::pow(10.0, rng.uniform(-4.0, -1.5));
    const double share = rng.uniform(0.1, 1.0);
    const double expected =
        all_pairs_longest_step(bodies, moves, h, [&](std::size_t i, std::size_t j) {
          return share * (bodies[i].shape().least_band() + bodies[j].shape().least_band());
        });
    EXPECT_EQ(planner.gentle_step(bodies, moves, kGravity, h, share), expected) << "case " << c;
    cut += expected < h ? 1 : 0;
    whole += expected == h ? 1 : 0;
  }
  EXPECT_GT(cut, 30);    // the cases do cut steps
  EXPECT_GT(whole, 30);  // and some are gentle all the way
}

// A disk resting in a floor's band moves gently; the same disk closing on the floor at 3 m/s
// does not: its gentle step is the time it takes to cover half the pair's bands.
TEST(StepPlanner, ResterMovesGentlyAndAnImpactDoesNot) {
  const Material m;
  std::vector<RigidBody> bodies;
  bodies.push_back(testing::floor_block(2.0, 0.2, 0.0, m, 2e-3));
  bodies.push_back(testing::disk(0.1, 32, Vec2(0.0, 0.1 + 1e-3), Vec2(0.0, -0.005), m, 2e-3));
  const std::vector<std::uint8_t> moves = {0, 1};
  StepPlanner planner;
  EXPECT_EQ(planner.gentle_step(bodies, moves, kGravity, 4e-3, 0.5), 4e-3);
  BodyState falling = bodies[1].state();
  falling.velocity = Vec2(0.0, -3.0);
  bodies[1].set_state(falling);
  const double bands = bodies[0].shape().least_band() + bodies[1].shape().least_band();
  const double h = planner.gentle_step(bodies, moves, kGravity, 4e-3, 0.5);
  EXPECT_LT(h, 1e-3);
  // 3 m/s·h + ½g·h² is half the bands.
  EXPECT_NEAR(3.0 * h + 0.5 * kGravity.norm() * h * h, 0.5 * bands, 1e-15);
}

// The relative reach the bound rests on holds for real motions: over free flight, no boundary
// point of a mover moves relative to any boundary point of another mover by more than
// (|v_i − v_j| + |ω_i|·r_i + |ω_j|·r_j)·dt (gravity moves both alike), and relative to a fixed
// body by more than |u_i|·dt + ½|g|·dt².
TEST(StepPlanner, RelativeReachBoundsEveryPairOfBoundaryPoints) {
  Rng rng(12);
  for (int c = 0; c < 100; ++c) {
    std::vector<std::uint8_t> moves;
    std::vector<RigidBody> bodies =
        random_crowd(rng, 2, std::pow(10.0, rng.uniform(-1.0, 3.0)), moves);
    // Half the cases: the two fall together, as bodies dropped side by side.
    if (c % 2 == 0 && !bodies[0].fixed() && !bodies[1].fixed()) {
      BodyState s = bodies[1].state();
      s.velocity = bodies[0].state().velocity;
      bodies[1].set_state(s);
    }
    if (bodies[0].fixed()) continue;
    const double dt = std::pow(10.0, rng.uniform(-5.0, -2.0));
    const BodyState& s0 = bodies[0].state();
    const BodyState& s1 = bodies[1].state();
    const bool both = !bodies[1].fixed();
    const double bound = both ? ((s0.velocity - s1.velocity).norm() +
                                 std::abs(s0.angular_velocity) * bodies[0].bounding_radius() +
                                 std::abs(s1.angular_velocity) * bodies[1].bounding_radius()) *
                                    dt
                              : bodies[0].boundary_speed() * dt + 0.5 * kGravity.norm() * dt * dt;
    RigidBody later0 = bodies[0];
    RigidBody later1 = bodies[1];
    later0.set_state(free_flight(s0, kGravity, dt));
    if (both) later1.set_state(free_flight(s1, kGravity, dt));
    double worst = 0.0;
    const PeriodicBSpline& c0 = bodies[0].curve();
    const PeriodicBSpline& c1 = bodies[1].curve();
    for (std::size_t j0 = 0; j0 < c0.size(); j0 += 3) {
      const Vec2 p = c0.point(j0, 0.5);
      const Vec2 move0 = later0.world_point(p) - bodies[0].world_point(p);
      for (std::size_t j1 = 0; j1 < c1.size(); j1 += 3) {
        const Vec2 q = c1.point(j1, 0.5);
        const Vec2 move1 = later1.world_point(q) - bodies[1].world_point(q);
        worst = std::max(worst, (move0 - move1).norm());
      }
    }
    EXPECT_LE(worst, bound * (1.0 + 1e-9) + 1e-15) << "case " << c;
  }
}

// Three 1 mm disks falling side by side under 94 g (issue 15): nothing approaches anything, so
// however fast they fall the steps stay near the longest step (1 ms), not a fraction of a
// microsecond (17.7 million steps in 2.6 s before the bound was relative).
TEST(StepPlanner, BodiesFallingTogetherTakeFullSteps) {
  WorldSettings settings;
  settings.gravity = Vec2(0.0, -922.0);
  World world(settings);
  const Material m;
  for (int k = 0; k < 3; ++k)
    world.add_body(testing::disk(0.0005, 12, Vec2(0.00102 * k, 0.0), Vec2::Zero(), m));
  for (int frame = 1; frame <= 30; ++frame)
    world.advance_to(frame / 30.0);
  EXPECT_LE(world.stats().steps, 10u * 1000u);
  EXPECT_EQ(world.stats().crossings, 0u);
}

// A scene scaled as a whole (lengths, speeds and gravity by the same factor) moves the same in
// time, so it must cost the same steps at 1 mm, 1 m and 1 km (issue 15: within 2×): a disk
// bouncing on a floor, one thrown across it, and two falling side by side.
TEST(StepPlanner, AWholeSceneScaledTakesTheSameSteps) {
  std::vector<std::uint64_t> steps;
  for (const double s : {1e-3, 1.0, 1e3}) {
    WorldSettings settings;
    settings.gravity = s * Vec2(0.0, -9.81);
    World world(settings);
    const Material m;
    world.add_body(testing::floor_block(8.0 * s, 0.4 * s, 0.0, m));
    world.add_body(testing::disk(0.1 * s, 16, s * Vec2(-1.0, 0.5), s * Vec2(0.0, 0.0), m));
    world.add_body(testing::disk(0.1 * s, 16, s * Vec2(1.0, 0.3), s * Vec2(-2.0, 1.0), m));
    world.add_body(testing::disk(0.05 * s, 16, s * Vec2(2.0, 1.0), Vec2::Zero(), m));
    world.add_body(testing::disk(0.05 * s, 16, s * Vec2(2.11, 1.0), Vec2::Zero(), m));
    for (int frame = 1; frame <= 30; ++frame)
      world.advance_to(frame / 30.0);
    EXPECT_EQ(world.stats().crossings, 0u) << "scale " << s;
    steps.push_back(world.stats().steps);
  }
  const auto [fewest, most] = std::minmax_element(steps.begin(), steps.end());
  EXPECT_LE(*most, 2 * *fewest) << steps[0] << " " << steps[1] << " " << steps[2];
  RecordProperty("steps", std::to_string(steps[0]) + " " + std::to_string(steps[1]) + " " +
                              std::to_string(steps[2]));
}

// When it says nothing can meet in h, nothing does: the boxes (bands included) of every pair with
// a mover stay apart at 200 instants of the free flight over h.
TEST(StepPlanner, NothingCanMeetIsNeverWrong) {
  Rng rng(9);
  StepPlanner planner;
  int free = 0;
  for (int c = 0; c < 300; ++c) {
    std::vector<std::uint8_t> moves;
    std::vector<RigidBody> bodies =
        random_crowd(rng, 2 + static_cast<std::size_t>(rng.uniform(0.0, 12.0)),
                     std::pow(10.0, rng.uniform(-1.0, 1.0)), moves);
    // A common drift half of the time: bodies moving together.
    if (rng.uniform() < 0.5) {
      const Vec2 drift(rng.uniform(-30.0, 30.0), rng.uniform(-30.0, 30.0));
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (moves[i] == 0) continue;
        BodyState s = bodies[i].state();
        s.velocity += drift;
        bodies[i].set_state(s);
      }
    }
    const double h = std::pow(10.0, rng.uniform(-3.0, -0.5));
    if (!planner.nothing_can_meet(bodies, moves, kGravity, h)) continue;
    ++free;
    std::vector<BodyState> start;
    for (const RigidBody& b : bodies)
      start.push_back(b.state());
    for (int k = 0; k <= 200; ++k) {
      const double t = h * k / 200.0;
      std::vector<Aabb> boxes;
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        RigidBody moved = bodies[i];
        if (moves[i] != 0) moved.set_state(free_flight(start[i], kGravity, t));
        boxes.push_back(moved.shape().world_bounds(moved.placement()));
      }
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
          if (moves[i] == 0 && moves[j] == 0) continue;
          ASSERT_FALSE(boxes[i].overlaps(boxes[j])) << "case " << c << " at t = " << t;
        }
      }
    }
  }
  EXPECT_GT(free, 50);
}

// A World whose bodies cannot meet takes one step per target time (and one more at each sleep
// check, every 0.25 s, where short steps would have ended too), and lands exactly on the
// closed-form free flight; three bodies falling together side by side at 50 m/s too.
TEST(StepPlanner, WorldStepsToTheTargetWhileNothingCanMeet) {
  WorldSettings settings;
  World world(settings);
  const Material m;
  for (int k = 0; k < 3; ++k) {
    world.add_body(testing::disk(0.05, 16, Vec2(0.3 * k, 100.0), Vec2(0.0, -50.0), m));
  }
  const BodyState start = world.body(0).state();
  for (int frame = 1; frame <= 30; ++frame)
    world.advance_to(frame / 30.0);
  EXPECT_LE(world.stats().steps, 30u + 5u);
  EXPECT_GE(world.stats().free_steps, 30u);
  const BodyState exact = free_flight(start, settings.gravity, 1.0);
  EXPECT_NEAR(world.body(0).state().position.y(), exact.position.y(), 1e-12 * 100.0);
  EXPECT_NEAR(world.body(0).state().velocity.y(), exact.velocity.y(), 1e-12 * 60.0);
}

// Rest steps: a rough disk dropped on a rough floor comes to rest in its band and sleeps as it
// does with every step near contact at max_step, in fewer steps, some of them rest steps, none
// crossing; with rest_stride 1 no step is a rest step.
TEST(StepPlanner, RestStepsLetARestingDiskTakeLongerStepsAndStillRestInItsBand) {
  auto run = [](int stride) {
    WorldSettings settings;
    settings.rest_stride = stride;
    World world(settings);
    const Material m = testing::make_material(0.5, 0.5);
    world.add_body(testing::floor_block(4.0, 0.4, 0.0, m, 2e-3), "floor");
    world.add_body(testing::disk(0.2, 48, Vec2(0.0, 0.3), Vec2::Zero(), m, 2e-3), "disk");
    for (int frame = 1; frame <= 60; ++frame)
      world.advance_to(frame / 20.0);
    return world;
  };
  const World every = run(1);
  const World rests = run(4);
  EXPECT_EQ(every.stats().rest_steps, 0u);
  EXPECT_GT(rests.stats().rest_steps, 100u);
  EXPECT_LT(rests.stats().steps, every.stats().steps);
  for (const World* world : {&every, &rests}) {
    EXPECT_EQ(world->stats().crossings, 0u);
    EXPECT_TRUE(world->asleep(1));
  }
  // Both rest in the pair's band (3.6 mm together): where they rest differs by less than it.
  EXPECT_NEAR(rests.body(1).state().position.y(), every.body(1).state().position.y(), 3.6e-3);
  RecordProperty("steps_every", std::to_string(every.stats().steps));
  RecordProperty("steps_rests", std::to_string(rests.stats().steps));
}

}  // namespace
}  // namespace rugosim
