#include "engine/dynamics/mid_step_rest.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::floor_block;
using testing::make_material;

constexpr double kG = 9.81;
constexpr double kRadius = 0.1;
constexpr double kLambda = 1e-5;  // m, each side's tolerance at the contact: band 2e-5 m

// A floor (body 0, top at y = 0) and a disk (body 1) resting on it at gap d, at rest.
std::vector<RigidBody> floor_and_disk(double gap, const Vec2& velocity = Vec2::Zero()) {
  std::vector<RigidBody> bodies;
  bodies.push_back(floor_block(8.0, 0.4, 0.0, make_material(0.0, 0.3)));
  bodies.push_back(disk(kRadius, 32, Vec2(0.0, kRadius + gap), velocity, make_material(0.0, 0.3)));
  return bodies;
}

// Their contact as the collision layer reports it: A is the floor (the lower index), the
// normal from the disk (B) towards the floor, the point halfway across the gap.
std::vector<ContactManifold> contact_at(double gap) {
  ContactManifold m;
  m.body_a = 0;
  m.body_b = 1;
  Contact c;
  c.point = Vec2(0.0, 0.5 * gap);
  c.point_a = Vec2::Zero();
  c.point_b = Vec2(0.0, gap);
  c.normal = Vec2(0.0, -1.0);
  c.distance = gap;
  c.lambda_a = c.lambda_b = kLambda;
  m.contacts.push_back(c);
  return {m};
}

MidStepRestSettings frictionless() {
  MidStepRestSettings s;
  s.gravity = Vec2(0.0, -kG);
  s.friction_gain = 0.0;
  s.sweeps.tolerance = 1e-12;
  s.sweeps.speed_floor = kG * 1e-3;
  return s;
}

// Deeper than its rest depth, a contact may not approach at all at mid-step: a body at rest
// leaves with exactly g·h/2 upwards, so that over the step (falling back to −g·h/2) it moves
// by nothing.
TEST(MidStepRest, AContactDeeperThanItsRestDepthStopsAtMidStepExactly) {
  const double band = 2.0 * kLambda;
  const double h = 1e-3;
  std::vector<RigidBody> bodies = floor_and_disk(0.25 * band);
  const std::vector<std::uint8_t> moves = {0, 1};
  const MidStepRestCounts counts =
      rest_at_mid_step(bodies, moves, contact_at(0.25 * band), h, frictionless());
  EXPECT_EQ(counts.contacts, 1u);
  EXPECT_EQ(counts.pushed, 1u);
  EXPECT_TRUE(counts.converged);
  const BodyState& s = bodies[1].state();
  EXPECT_NEAR(s.velocity.y(), 0.5 * kG * h, 1e-12);
  EXPECT_EQ(s.velocity.x(), 0.0);
  EXPECT_NEAR(s.angular_velocity, 0.0, 1e-12);
  ASSERT_EQ(counts.rested.size(), 1u);
  EXPECT_EQ(counts.rested[0].allowance, 0.0);
}

// Above its rest depth, a contact may close to it within the step: the allowance is
// (d − (1 − rest_depth)·λ)/h, and the body keeps that approach at mid-step. With a long step
// (4 ms) gravity's g·h/2 is more than the allowance, so the body gets the difference; with a
// short one (0.25 ms) it is less, and the body gets nothing.
TEST(MidStepRest, AContactAboveItsRestDepthMayCloseToItWithinTheStep) {
  const double band = 2.0 * kLambda;
  const double gap = 0.9 * band;
  const double h = 4e-3;
  std::vector<RigidBody> bodies = floor_and_disk(gap);
  const std::vector<std::uint8_t> moves = {0, 1};
  const MidStepRestCounts counts =
      rest_at_mid_step(bodies, moves, contact_at(gap), h, frictionless());
  const double allowance = (gap - (1.0 - frictionless().rest_depth) * band) / h;
  ASSERT_LT(allowance, 0.5 * kG * h);
  EXPECT_NEAR(bodies[1].state().velocity.y(), 0.5 * kG * h - allowance, 1e-12);
  ASSERT_EQ(counts.rested.size(), 1u);
  EXPECT_NEAR(counts.rested[0].allowance, allowance, 1e-15);
  std::vector<RigidBody> short_step = floor_and_disk(gap);
  const MidStepRestCounts none =
      rest_at_mid_step(short_step, moves, contact_at(gap), 2.5e-4, frictionless());
  EXPECT_EQ(none.pushed, 0u);
  EXPECT_EQ(short_step[1].state().velocity, Vec2::Zero());
}

// With friction enough to hold it, a sliding contact's slip at mid-step is stopped; the body's
// own motion (slip plus spin) is what the Coulomb cone allows, no more.
TEST(MidStepRest, FrictionStopsTheSlipAtMidStepWithinTheCone) {
  const double band = 2.0 * kLambda;
  const double h = 1e-3;
  for (const double speed : {1e-3, 1.0}) {
    std::vector<RigidBody> bodies = floor_and_disk(0.25 * band, Vec2(speed, 0.0));
    // A rough floor (σ = 1 cm everywhere: λ = 9 mm) gives μ = 100/m · 9 mm = 0.9.
    bodies[0] = floor_block(8.0, 0.4, 0.0, make_material(0.0, 0.3), 0.01);
    const std::vector<std::uint8_t> moves = {0, 1};
    MidStepRestSettings s = frictionless();
    s.friction_gain = 100.0;
    const MidStepRestCounts counts = rest_at_mid_step(bodies, moves, contact_at(0.25 * band), h, s);
    ASSERT_EQ(counts.pushed, 1u);
    const BodyState& st = bodies[1].state();
    const double normal_change = st.velocity.y();  // the normal impulse per kg
    const double slip_change = st.velocity.x() - speed;
    const double mu = bodies[0].friction_coefficient(0, 0.0, 100.0);
    ASSERT_NEAR(mu, 0.9, 1e-12);
    // The contact's slip at mid-step: v_x + ω·r (the point is r below the centre).
    const double slip = st.velocity.x() + st.angular_velocity * (kRadius + 0.125 * band);
    if (speed == 1e-3) {
      EXPECT_NEAR(slip, 0.0, 1e-9) << "a slow slip is stopped";
    } else {
      // A fast one is slowed by μ times the normal impulse, exactly.
      EXPECT_NEAR(std::abs(slip_change), mu * normal_change, 1e-9 * speed);
      EXPECT_GT(slip, 0.0);
    }
  }
}

// Only bodies that move in the step are pushed; contacts of crossing pairs are the back-off's.
TEST(MidStepRest, HeldBodiesAndCrossingPairsGetNothing) {
  const double band = 2.0 * kLambda;
  std::vector<RigidBody> bodies = floor_and_disk(0.25 * band);
  const std::vector<std::uint8_t> held = {0, 0};
  const MidStepRestCounts none =
      rest_at_mid_step(bodies, held, contact_at(0.25 * band), 1e-3, frictionless());
  EXPECT_EQ(none.contacts, 0u);
  EXPECT_TRUE(none.rested.empty());
  std::vector<ContactManifold> crossing = contact_at(0.25 * band);
  crossing[0].intersections.push_back({0, 0, 0.5, 0.5, Vec2::Zero()});
  const std::vector<std::uint8_t> moves = {0, 1};
  const MidStepRestCounts skipped = rest_at_mid_step(bodies, moves, crossing, 1e-3, frictionless());
  EXPECT_EQ(skipped.contacts, 0u);
  EXPECT_EQ(bodies[1].state().velocity, Vec2::Zero());
}

TEST(MidStepRest, FindRestedFindsExactlyThePairsGiven) {
  const std::vector<RestedPair> rested = {{0, 3, 0.1}, {1, 2, 0.2}, {1, 5, 0.3}, {4, 5, 0.4}};
  for (const RestedPair& r : rested) {
    const RestedPair* found = find_rested(rested, r.body_a, r.body_b);
    ASSERT_NE(found, nullptr);
    EXPECT_EQ(found->allowance, r.allowance);
  }
  EXPECT_EQ(find_rested(rested, 0, 1), nullptr);
  EXPECT_EQ(find_rested(rested, 1, 3), nullptr);
  EXPECT_EQ(find_rested(rested, 5, 4), nullptr);
  EXPECT_EQ(find_rested(rested, 9, 9), nullptr);
  EXPECT_EQ(find_rested({}, 0, 3), nullptr);
}

}  // namespace
}  // namespace rugosim
