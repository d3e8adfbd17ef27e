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
  double safe = h;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (moves[i] == 0) continue;
    for (std::size_t j = 0; j < bodies.size(); ++j) {
      if (j == i || (moves[j] != 0 && j < i)) continue;
      const bool j_moves = moves[j] != 0;
      const double a = bodies[i].boundary_speed() + (j_moves ? bodies[j].boundary_speed() : 0.0);
      const double b = j_moves ? 0.0 : 0.5 * g;
      const double reach = a * h + b * h * h;
      const double limit = 0.5 * std::min(bodies[i].thickness(), bodies[j].thickness());
      if (reach <= limit) continue;
      Aabb grown = bodies[i].shape().world_bounds(bodies[i].placement());
      grown.min -= Vec2::Constant(reach);
      grown.max += Vec2::Constant(reach);
      if (!grown.overlaps(bodies[j].shape().world_bounds(bodies[j].placement()))) continue;
      const double dt =
          b > 0.0 ? 2.0 * limit / (a + std::sqrt(a * a + 4.0 * b * limit)) : limit / a;
      safe = std::min(safe, dt);
    }
  }
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

}  // namespace
}  // namespace rugosim
