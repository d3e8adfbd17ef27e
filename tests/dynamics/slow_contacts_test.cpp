#include "engine/dynamics/slow_contacts.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/dynamics/collision_impulse.h"

namespace rugosim {
namespace {

constexpr double kTolerance = 1e-12;

// A uniform disk of `mass` kg and `radius` m at `centre`, moving at `velocity`.
SolverBody disk(double mass, double radius, const Vec2& centre, const Vec2& velocity,
                double angular_velocity = 0.0) {
  SolverBody b;
  b.inverse_mass = 1.0 / mass;
  b.inverse_inertia = 2.0 / (mass * radius * radius);
  b.position = centre;
  b.velocity = velocity;
  b.angular_velocity = angular_velocity;
  return b;
}

SolverBody fixed_floor() {
  return SolverBody{};
}

// The contact of `body` (a disk of `radius` m) with the floor (body 0) below it.
SlowContact on_floor(std::size_t body, const SolverBody& b, double radius, double allowance,
                     double mu) {
  SlowContact c;
  c.body_a = body;
  c.body_b = 0;
  c.point = b.position - Vec2(0.0, radius);
  c.normal = Vec2::UnitY();
  c.allowance = allowance;
  c.friction = mu;
  return c;
}

// The relative velocity at contact c after the solve's changes.
Vec2 velocity_after(const std::vector<SolverBody>& bodies, const SlowContactResult& r,
                    const SlowContact& c) {
  const auto state = [&](std::size_t i) {
    const SolverBody& b = bodies[i];
    return ContactBodyState{b.inverse_mass, b.inverse_inertia, b.velocity + r.change[i].velocity,
                            b.angular_velocity + r.change[i].angular_velocity,
                            c.point - b.position};
  };
  return relative_contact_velocity(state(c.body_a), state(c.body_b));
}

SweepSettings settings() {
  return SweepSettings{64, 1e-12, 9.81e-3};
}

TEST(SlowContacts, AnApproachFasterThanItsAllowanceEndsAtTheAllowanceExactly) {
  const double mass = 2.0, radius = 0.1, v = 0.02, allowance = 0.005;
  const std::vector<SolverBody> bodies{fixed_floor(),
                                       disk(mass, radius, Vec2(0.0, radius), Vec2(0.0, -v))};
  std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, allowance, 0.5)};
  const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
  ASSERT_TRUE(r.converged) << r.residual;
  EXPECT_EQ(r.pushed, 1u);
  EXPECT_NEAR(velocity_after(bodies, r, contacts[0]).y(), -allowance, kTolerance);
  EXPECT_NEAR(contacts[0].impulse.x(), mass * (v - allowance), kTolerance);
  EXPECT_NEAR(contacts[0].impulse.y(), 0.0, kTolerance);
  EXPECT_NEAR(r.change[1].angular_velocity, 0.0, kTolerance);
  EXPECT_EQ(r.change[0].velocity, Vec2::Zero());  // the floor is fixed
}

TEST(SlowContacts, ASeparatingContactOrOneWithinItsAllowanceGetsNoImpulse) {
  const double radius = 0.1, allowance = 0.005;
  for (const double vy : {0.3, 0.0, -0.5 * allowance}) {
    const std::vector<SolverBody> bodies{fixed_floor(),
                                         disk(1.0, radius, Vec2(0.0, radius), Vec2(0.2, vy))};
    std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, allowance, 0.5)};
    const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.sweeps, 1);
    EXPECT_EQ(r.pushed, 0u);
    EXPECT_EQ(contacts[0].impulse, Vec2::Zero()) << vy;
    EXPECT_EQ(r.change[1].velocity, Vec2::Zero()) << vy;  // no friction without a normal impulse
  }
}

// A disk landing slowly while it slides: the impulse m·Δv_n stops the slip when the cone holds
// it (|u_t| ≤ 3μΔv_n for a disk, K_tt = 3/m), else takes μ of it off the centre's speed.
TEST(SlowContacts, FrictionStopsTheSlipWithinTheConeAndSlidesOnTheConeOutsideIt) {
  const double mass = 1.5, radius = 0.2, v = 0.01, mu = 0.4;
  const double pushed = v;  // allowance 0
  for (const double slip : {0.5 * 3.0 * mu * pushed, 2.0 * 3.0 * mu * pushed}) {
    const std::vector<SolverBody> bodies{fixed_floor(),
                                         disk(mass, radius, Vec2(0.0, radius), Vec2(slip, -v))};
    std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, 0.0, mu)};
    const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
    ASSERT_TRUE(r.converged);
    const Vec2 after = velocity_after(bodies, r, contacts[0]);
    EXPECT_NEAR(after.y(), 0.0, kTolerance);
    EXPECT_NEAR(contacts[0].impulse.x(), mass * pushed, kTolerance);
    if (slip <= 3.0 * mu * pushed) {
      EXPECT_NEAR(after.x(), 0.0, kTolerance) << "rolls";
      EXPECT_NEAR(r.change[1].velocity.x(), -slip / 3.0, kTolerance);
    } else {
      // t = perp(n) = −x here: friction pushes the disk back along −x.
      EXPECT_NEAR(contacts[0].impulse.y(), mu * contacts[0].impulse.x(), kTolerance);
      EXPECT_NEAR(r.change[1].velocity.x(), -mu * pushed, kTolerance);
      EXPECT_NEAR(after.x(), slip - 3.0 * mu * pushed, kTolerance) << "still slides, same way";
    }
  }
}

// Two equal disks falling together in a column onto the floor: the inelastic answer stops both,
// the floor carries 2mv and the contact between them mv. Answered one contact at a time, the
// lower disk stops and the upper one then pushes it into the floor again, pass after pass.
TEST(SlowContacts, AColumnLandingTogetherStopsAsOneWithTheFloorCarryingBoth) {
  const double mass = 0.7, radius = 0.05, v = 0.01;
  const std::vector<SolverBody> bodies{fixed_floor(),
                                       disk(mass, radius, Vec2(0.0, radius), Vec2(0.0, -v)),
                                       disk(mass, radius, Vec2(0.0, 3.0 * radius), Vec2(0.0, -v))};
  std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, 0.0, 0.3)};
  SlowContact between;
  between.body_a = 2;
  between.body_b = 1;
  between.point = Vec2(0.0, 2.0 * radius);
  between.normal = Vec2::UnitY();
  between.friction = 0.3;
  contacts.push_back(between);
  const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
  ASSERT_TRUE(r.converged) << r.residual;
  EXPECT_GT(r.sweeps, 1);
  for (std::size_t i : {1u, 2u})
    EXPECT_NEAR((bodies[i].velocity + r.change[i].velocity).norm(), 0.0, 1e-9 * v) << i;
  EXPECT_NEAR(contacts[0].impulse.x(), 2.0 * mass * v, 1e-9 * mass * v);
  EXPECT_NEAR(contacts[1].impulse.x(), mass * v, 1e-9 * mass * v);
}

TEST(SlowContacts, ItsOwnSolutionAsAWarmStartConvergesInOneSweepToTheSameImpulses) {
  const double mass = 0.7, radius = 0.05;
  const std::vector<SolverBody> bodies{
      fixed_floor(), disk(mass, radius, Vec2(0.0, radius), Vec2(0.003, -0.02), 0.4),
      disk(mass, radius, Vec2(0.01, 3.0 * radius), Vec2(-0.002, -0.01), -0.1)};
  std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, 0.001, 0.3)};
  SlowContact between;
  between.body_a = 2;
  between.body_b = 1;
  between.point = Vec2(0.005, 2.0 * radius);
  between.normal = Vec2(0.1, 1.0).normalized();
  between.friction = 0.6;
  contacts.push_back(between);
  std::vector<SlowContact> cold = contacts;
  const SlowContactResult first = solve_slow_contacts(bodies, cold, settings());
  ASSERT_TRUE(first.converged);
  std::vector<SlowContact> warm = cold;
  const SlowContactResult second = solve_slow_contacts(bodies, warm, settings());
  EXPECT_TRUE(second.converged);
  EXPECT_EQ(second.sweeps, 1);
  for (std::size_t i = 0; i < contacts.size(); ++i)
    EXPECT_LT((warm[i].impulse - cold[i].impulse).norm(), 1e-9 * cold[i].impulse.norm()) << i;
  // And the same call twice gives the same bits.
  std::vector<SlowContact> again = contacts;
  const SlowContactResult third = solve_slow_contacts(bodies, again, settings());
  for (std::size_t i = 0; i < contacts.size(); ++i)
    EXPECT_EQ(again[i].impulse, cold[i].impulse);
  EXPECT_EQ(third.sweeps, first.sweeps);
}

// A warm start outside the cone (a pull, or more friction than μ allows) is clamped into it
// first, and the one contact's answer is the cold start's.
TEST(SlowContacts, AWarmStartOutsideTheConeIsClampedAndChangesNotTheAnswer) {
  const double mass = 1.5, radius = 0.2, mu = 0.4;
  const std::vector<SolverBody> bodies{fixed_floor(),
                                       disk(mass, radius, Vec2(0.0, radius), Vec2(0.003, -0.01))};
  std::vector<SlowContact> cold{on_floor(1, bodies[1], radius, 0.0, mu)};
  solve_slow_contacts(bodies, cold, settings());
  for (const Vec2& warm : {Vec2(-3.0, 5.0), Vec2(2.0, -5.0), Vec2(0.001, 0.5)}) {
    std::vector<SlowContact> contacts{on_floor(1, bodies[1], radius, 0.0, mu)};
    contacts[0].impulse = warm;
    const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
    EXPECT_TRUE(r.converged) << warm.transpose();
    EXPECT_LT((contacts[0].impulse - cold[0].impulse).norm(), 1e-12) << warm.transpose();
    EXPECT_LE(std::abs(contacts[0].impulse.y()), mu * contacts[0].impulse.x() * (1.0 + 1e-12));
  }
}

TEST(SlowContacts, AContactBetweenFixedBodiesStaysAtZeroWhateverItsWarmStart) {
  const std::vector<SolverBody> bodies{fixed_floor(), fixed_floor()};
  SlowContact c;
  c.body_a = 1;
  c.body_b = 0;
  c.friction = 0.5;
  c.impulse = Vec2(3.0, 1.0);
  std::vector<SlowContact> contacts{c};
  const SlowContactResult r = solve_slow_contacts(bodies, contacts, settings());
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(contacts[0].impulse, Vec2::Zero());
  EXPECT_EQ(r.pushed, 0u);
}

}  // namespace
}  // namespace rugosim
