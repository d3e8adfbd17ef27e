#include "engine/dynamics/free_flight.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/geometry/shapes.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::scientific;

constexpr int kCases = 1000;

BodyState random_state(Rng& rng) {
  BodyState s;
  s.position = Vec2(rng.uniform(-10, 10), rng.uniform(-10, 10));
  s.angle = rng.uniform(-50, 50);
  s.velocity = Vec2(rng.uniform(-20, 20), rng.uniform(-20, 20));
  s.angular_velocity = rng.uniform(-30, 30);
  return s;
}

Vec2 random_gravity(Rng& rng) {
  return Vec2(rng.uniform(-3, 3), rng.uniform(-15, 0));
}

// A length and an angle scale for relative comparisons after a flight of duration t.
double length_scale(const BodyState& s, const Vec2& g, double t) {
  return s.position.norm() + s.velocity.norm() * t + 0.5 * g.norm() * t * t + 1.0;
}

double state_error(const BodyState& a, const BodyState& b, const BodyState& start, const Vec2& g,
                   double t) {
  const double length = length_scale(start, g, t);
  const double speed = start.velocity.norm() + g.norm() * t + 1.0;
  const double angle = std::abs(start.angle) + std::abs(start.angular_velocity) * t + 1.0;
  return std::max({(a.position - b.position).norm() / length,
                   (a.velocity - b.velocity).norm() / speed, std::abs(a.angle - b.angle) / angle,
                   std::abs(a.angular_velocity - b.angular_velocity) /
                       (std::abs(start.angular_velocity) + 1.0)});
}

TEST(FreeFlight, MatchesTheClosedForm) {
  Rng rng(701);
  double worst = 0.0;
  for (int c = 0; c < kCases; ++c) {
    const BodyState s = random_state(rng);
    const Vec2 g = random_gravity(rng);
    const double t = rng.uniform(0.0, 5.0);
    const BodyState f = free_flight(s, g, t);
    // The closed form, evaluated in extended precision and a different grouping.
    const long double lt = t;
    for (int i = 0; i < 2; ++i) {
      const long double x = s.position[i] + lt * (s.velocity[i] + 0.5L * g[i] * lt);
      const long double v = s.velocity[i] + g[i] * lt;
      const double length = length_scale(s, g, t);
      const double err = std::abs(static_cast<double>(f.position[i] - x)) / length;
      worst = std::max(worst, err);
      EXPECT_LE(err, 1e-15);
      const double speed = s.velocity.norm() + g.norm() * t + 1.0;
      EXPECT_LE(std::abs(static_cast<double>(f.velocity[i] - v)), 1e-15 * speed);
    }
    EXPECT_NEAR(f.angle, s.angle + s.angular_velocity * t, 1e-15 * (std::abs(s.angle) + 1e3));
    EXPECT_EQ(f.angular_velocity, s.angular_velocity);
  }
  RecordProperty("worst_relative_position_error", scientific(worst));
}

TEST(FreeFlight, AdvancingInPiecesEqualsAdvancingAtOnce) {
  Rng rng(702);
  double worst_two = 0.0, worst_many = 0.0;
  for (int c = 0; c < kCases; ++c) {
    const BodyState s = random_state(rng);
    const Vec2 g = random_gravity(rng);
    const double dt1 = rng.uniform(0.0, 3.0), dt2 = rng.uniform(0.0, 3.0);
    const BodyState two = free_flight(free_flight(s, g, dt1), g, dt2);
    const BodyState once = free_flight(s, g, dt1 + dt2);
    const double err = state_error(two, once, s, g, dt1 + dt2);
    worst_two = std::max(worst_two, err);
    EXPECT_LE(err, 1e-12) << "case " << c;

    if (c % 10 == 0) {
      // 1000 unequal steps, as a stepping loop cut short by contacts would take.
      BodyState many = s;
      double total = 0.0;
      for (int k = 0; k < 1000; ++k) {
        const double dt = rng.uniform(0.0, 2e-3);
        many = free_flight(many, g, dt);
        total += dt;
      }
      const double err_many = state_error(many, free_flight(s, g, total), s, g, total);
      worst_many = std::max(worst_many, err_many);
      EXPECT_LE(err_many, 1e-12) << "case " << c;
    }
  }
  RecordProperty("worst_relative_error_two_steps", scientific(worst_two));
  RecordProperty("worst_relative_error_1000_steps", scientific(worst_many));
}

// A random state, gravity and flight time in [0, 5] s.
struct FlightCase {
  BodyState s;
  Vec2 g;
  double t;
};
FlightCase random_case(Rng& rng) {
  const BodyState s = random_state(rng);
  const Vec2 g = random_gravity(rng);
  return {s, g, rng.uniform(0.0, 5.0)};
}

TEST(DrivenFlight, WithoutAngularAccelerationIsFreeFlightBitForBit) {
  Rng rng(711);
  for (int c = 0; c < kCases; ++c) {
    const auto [s, g, t] = random_case(rng);
    const BodyState f = free_flight(s, g, t);
    const BodyState d = driven_flight(s, g, 0.0, t);
    EXPECT_EQ(f.position, d.position);
    EXPECT_EQ(f.velocity, d.velocity);
    EXPECT_EQ(f.angle, d.angle);
    EXPECT_EQ(f.angular_velocity, d.angular_velocity);
  }
}

TEST(DrivenFlight, MatchesTheClosedFormAndRunsInPieces) {
  Rng rng(712);
  for (int c = 0; c < kCases; ++c) {
    const BodyState s = random_state(rng);
    const Vec2 a = random_gravity(rng);
    const double alpha = rng.uniform(-100.0, 100.0);
    const double t = rng.uniform(0.0, 2.0);
    const BodyState d = driven_flight(s, a, alpha, t);
    const long double lt = t;
    const long double angle = s.angle + lt * (s.angular_velocity + 0.5L * alpha * lt);
    const double angle_scale =
        std::abs(s.angle) + std::abs(s.angular_velocity) * t + std::abs(alpha) * t * t + 1.0;
    EXPECT_LE(std::abs(static_cast<double>(d.angle - angle)), 1e-15 * angle_scale);
    EXPECT_NEAR(d.angular_velocity, s.angular_velocity + alpha * t,
                1e-15 * (std::abs(s.angular_velocity) + std::abs(alpha) * t + 1.0));
    // A constant acceleration is the same motion taken in two pieces.
    const double t1 = rng.uniform(0.0, t);
    const BodyState two = driven_flight(driven_flight(s, a, alpha, t1), a, alpha, t - t1);
    EXPECT_LE(state_error(two, d, s, a, t), 1e-13);
  }
}

TEST(FreeFlight, RunningBackwardsUndoesTheFlight) {
  Rng rng(703);
  for (int c = 0; c < kCases; ++c) {
    const auto [s, g, t] = random_case(rng);
    const BodyState back = free_flight(free_flight(s, g, t), g, -t);
    EXPECT_LE(state_error(back, s, s, g, t), 1e-13);
  }
}

// Kinetic energy plus potential energy −m·g·x is constant along the flight.
TEST(FreeFlight, ConservesMechanicalEnergy) {
  RigidBodyDesc desc;
  desc.control_points = ellipse_control_points(0.5, 0.2, 20);
  desc.velocity = Vec2(2.0, 7.0);
  desc.angular_velocity = 4.0;
  const Vec2 g(0.5, -9.81);
  RigidBody body(desc);
  const Vec2 x0 = body.state().position;
  const double e0 = body.kinetic_energy();
  for (int k = 0; k < 100; ++k) {
    advance_free_flight(body, g, 0.0137 * k);
    const double energy = body.kinetic_energy() - body.mass() * g.dot(body.state().position - x0);
    EXPECT_NEAR(energy, e0, 1e-12 * (e0 + body.kinetic_energy()));
  }
}

TEST(FreeFlight, AdvancingABodyMovesItsPlacementAndLeavesTheAngleUnwrapped) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(0.4, 0.2, 12);
  desc.angular_velocity = 10.0;
  RigidBody body(desc);
  advance_free_flight(body, Vec2(0.0, -9.81), 10.0);
  EXPECT_DOUBLE_EQ(body.state().angle, 100.0);
  EXPECT_EQ(body.placement().translation(), body.state().position);
  EXPECT_DOUBLE_EQ(body.state().position.y(), -0.5 * 9.81 * 100.0);
  const Transform2 expected(100.0, body.state().position);
  EXPECT_EQ(body.placement().cos_angle(), expected.cos_angle());
  EXPECT_EQ(body.placement().sin_angle(), expected.sin_angle());
}

TEST(FreeFlight, ProjectileReachesItsApexHeightAndLandsAtTwiceTheApexTime) {
  const double g = 9.81;
  const Vec2 gravity(0.0, -g);
  BodyState s;
  s.velocity = Vec2(1.5, 4.0);
  const double t_apex = *apex_time(s.velocity, gravity);
  EXPECT_NEAR(t_apex, 4.0 / g, 1e-15);
  const BodyState apex = free_flight(s, gravity, t_apex);
  EXPECT_NEAR(apex.velocity.y(), 0.0, 1e-15);
  EXPECT_NEAR(apex.position.y(), 16.0 / (2.0 * g), 1e-15);
  EXPECT_NEAR(*apex_rise(s.velocity, gravity), 16.0 / (2.0 * g), 1e-15);

  const double t_land = *time_to_fall(s.velocity, gravity, 0.0);
  EXPECT_NEAR(t_land, 2.0 * t_apex, 1e-15);
  EXPECT_NEAR(free_flight(s, gravity, t_land).position.y(), 0.0, 1e-14);
  EXPECT_NEAR(free_flight(s, gravity, t_land).position.x(), 1.5 * t_land, 1e-14);

  // Landing on a ledge 2 m below the launch point, rising or falling at the start.
  for (double vy : {4.0, 0.0, -3.0, -1e8}) {
    const Vec2 v(0.7, vy);
    const double t = *time_to_fall(v, gravity, 2.0);
    EXPECT_GT(t, 0.0);
    EXPECT_NEAR(
        free_flight(s.velocity == v ? s : BodyState{{0, 0}, 0, v, 0}, gravity, t).position.y(),
        -2.0, 1e-12 * (1.0 + std::abs(vy) * t));
  }
  // Once falling, the apex has passed and the body rises no more.
  EXPECT_LT(*apex_time(Vec2(0.0, -1.0), gravity), 0.0);
  EXPECT_EQ(*apex_rise(Vec2(0.0, -1.0), gravity), 0.0);
  EXPECT_EQ(*time_to_fall(Vec2(0.0, -1.0), gravity, 0.0), 0.0);
  EXPECT_FALSE(time_to_fall(Vec2(0.0, 1.0), gravity, -1.0).has_value());
}

// "Up" is against gravity whichever way it points.
TEST(FreeFlight, TimeOfFlightHelpersDoNotDependOnTheDirectionOfGravity) {
  Rng rng(704);
  for (int c = 0; c < kCases; ++c) {
    const double g = rng.uniform(0.1, 20.0), u = rng.uniform(-10.0, 10.0);
    const double side = rng.uniform(-5.0, 5.0), drop = rng.uniform(0.0, 3.0);
    const double turn = rng.uniform(-std::numbers::pi, std::numbers::pi);
    const Transform2 r(turn, Vec2::Zero());
    const Vec2 gravity = r.rotate(Vec2(0.0, -g)), velocity = r.rotate(Vec2(side, u));
    EXPECT_NEAR(*apex_time(velocity, gravity), u / g, 1e-13 * (1.0 + std::abs(u / g)));
    EXPECT_NEAR(*apex_rise(velocity, gravity), u > 0 ? u * u / (2 * g) : 0.0,
                1e-12 * (1.0 + u * u / g));
    const double t = *time_to_fall(velocity, gravity, drop);
    BodyState start;
    start.velocity = velocity;
    const BodyState f = free_flight(start, gravity, t);
    EXPECT_NEAR(f.position.dot(-gravity / g), -drop, 1e-12 * (1.0 + drop + u * u / g));
    EXPECT_LE(f.velocity.dot(-gravity / g), 1e-12 * (1.0 + std::abs(u)));  // falling, or at rest
  }
  EXPECT_FALSE(apex_time(Vec2(1.0, 2.0), Vec2::Zero()).has_value());
  EXPECT_FALSE(apex_rise(Vec2(1.0, 2.0), Vec2::Zero()).has_value());
  EXPECT_FALSE(time_to_fall(Vec2(1.0, -2.0), Vec2::Zero(), 1.0).has_value());
}

// No point of the body strays farther than motion_bound at any instant of the interval.
TEST(FreeFlight, MotionBoundHoldsForEveryPointAtEveryInstant) {
  Rng rng(705);
  double tightest = 0.0;
  for (int c = 0; c < 200; ++c) {
    const BodyState s = random_state(rng);
    const Vec2 g = random_gravity(rng);
    const double dt = rng.uniform(0.0, 0.5), radius = rng.uniform(0.01, 2.0);
    const double bound = motion_bound(s, g, dt, radius);
    const Transform2 start(s.angle, s.position);
    for (int p = 0; p < 8; ++p) {
      const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const Vec2 body_point = rng.uniform(0.0, radius) * Vec2(std::cos(a), std::sin(a));
      for (int k = 0; k <= 50; ++k) {
        const BodyState f = free_flight(s, g, dt * k / 50.0);
        const double moved =
            (Transform2(f.angle, f.position).apply(body_point) - start.apply(body_point)).norm();
        EXPECT_LE(moved, bound * (1.0 + 1e-12) + 1e-12);
        tightest = std::max(tightest, moved / bound);
      }
    }
  }
  // Straight down from rest, without spin, the bound is exact.
  BodyState rest;
  EXPECT_DOUBLE_EQ(motion_bound(rest, Vec2(0, -9.81), 0.2, 1.0), 0.5 * 9.81 * 0.04);
  EXPECT_DOUBLE_EQ((free_flight(rest, Vec2(0, -9.81), 0.2).position).norm(), 0.5 * 9.81 * 0.04);
  RecordProperty("largest_fraction_of_bound_reached", scientific(tightest));
}

}  // namespace
}  // namespace rugosim
