#include "engine/dynamics/contact_forces.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/dynamics/free_flight.h"

namespace rugosim {
namespace {

constexpr double kG = 9.81;
constexpr double kStep = 1e-3;

// A box of 2·half_width × 2·half_height and `mass` kg, its centre at `centre`.
ForceBody box(double mass, double half_width, double half_height, const Vec2& centre) {
  ForceBody b;
  b.inverse_mass = 1.0 / mass;
  b.inverse_inertia = 3.0 / (mass * (half_width * half_width + half_height * half_height));
  b.position = centre;
  return b;
}

ForceBody fixed_floor() {
  return ForceBody{};
}

// Two contacts at the box's bottom corners, on a floor through the origin whose up is `up`.
std::vector<ForceContact> corners_on_floor(std::size_t body, const ForceBody& b, const Vec2& up,
                                           double half_width, double half_height, double mu) {
  const Vec2 along(up.y(), -up.x());
  std::vector<ForceContact> contacts;
  for (const double side : {-1.0, 1.0}) {
    ForceContact c;
    c.body_a = body;
    c.body_b = 0;
    c.point = b.position - half_height * up + side * half_width * along;
    c.normal = up;
    c.friction = mu;
    contacts.push_back(c);
  }
  return contacts;
}

BodyState state_of(const ForceBody& b) {
  BodyState s;
  s.position = b.position;
  s.velocity = b.velocity;
  s.angular_velocity = b.angular_velocity;
  return s;
}

TEST(ContactForces, ABoxAtRestOnAFloorEndsTheStepAtRestHeldByItsWeight) {
  const double mass = 3.0, w = 0.2, hh = 0.1;
  const std::vector<ForceBody> bodies{fixed_floor(), box(mass, w, hh, Vec2(0.0, hh))};
  std::vector<ForceContact> contacts = corners_on_floor(1, bodies[1], Vec2::UnitY(), w, hh, 0.5);
  const ForceResult r = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep);
  ASSERT_TRUE(r.converged) << r.residual;
  EXPECT_NEAR(contacts[0].force.x() + contacts[1].force.x(), mass * kG, 1e-9 * mass * kG);
  EXPECT_NEAR(contacts[0].force.x(), contacts[1].force.x(), 1e-9 * mass * kG);
  EXPECT_NEAR(contacts[0].force.y() + contacts[1].force.y(), 0.0, 1e-9 * mass * kG);
  EXPECT_LE(r.acceleration[1].norm(), 1e-9 * kG);
  EXPECT_LE(std::abs(r.angular_acceleration[1]) * w, 1e-9 * kG);
  EXPECT_EQ(r.acceleration[0], Vec2::Zero());  // the floor is fixed

  // Driven by these forces the box ends the step where it was, at rest: no hop, no sinking,
  // whatever ½gh² is against the band.
  const BodyState end =
      driven_flight(state_of(bodies[1]), r.acceleration[1], r.angular_acceleration[1], kStep);
  EXPECT_LE(end.velocity.norm(), 1e-9 * kG * kStep);
  EXPECT_LE((end.position - bodies[1].position).norm(), 1e-9 * kG * kStep * kStep);
}

// A box on an incline of angle θ with friction μ, released at rest.
struct Incline {
  double theta = 0.0;
  double mu = 0.0;
  double mass = 2.0, w = 0.15, hh = 0.05;
  std::vector<ForceBody> bodies;
  std::vector<ForceContact> contacts;
  Vec2 up, down_slope;

  Incline(double theta_deg, double friction) : theta(theta_deg * std::numbers::pi / 180.0) {
    mu = friction;
    up = Vec2(-std::sin(theta), std::cos(theta));
    down_slope = Vec2(-std::cos(theta), -std::sin(theta));
    bodies = {fixed_floor(), box(mass, w, hh, hh * up)};
    contacts = corners_on_floor(1, bodies[1], up, w, hh, mu);
  }
};

TEST(ContactForces, ABoxOnAnInclineBelowTheFrictionAngleSticks) {
  for (const double deg : {5.0, 20.0, 26.0}) {
    Incline in(deg, 0.5);  // tan 26.57° = 0.5
    const ForceResult r = solve_contact_forces(in.bodies, in.contacts, Vec2(0.0, -kG), kStep);
    ASSERT_TRUE(r.converged) << deg;
    const double weight = in.mass * kG;
    double normal = 0.0, tangent = 0.0;
    for (const ForceContact& c : in.contacts) {
      // Inside the cone, up to the solver's tolerance (the last normal update can follow the
      // last clamp of friction).
      EXPECT_LE(std::abs(c.force.y()), in.mu * c.force.x() + 1e-9 * in.mass * kG) << deg;
      normal += c.force.x();
      tangent += c.force.y();
    }
    EXPECT_NEAR(normal, weight * std::cos(in.theta), 1e-9 * weight) << deg;
    EXPECT_NEAR(std::abs(tangent), weight * std::sin(in.theta), 1e-9 * weight) << deg;
    EXPECT_LE(r.acceleration[1].norm(), 1e-9 * kG) << deg;
    EXPECT_LE(std::abs(r.angular_acceleration[1]) * in.w, 1e-9 * kG) << deg;
  }
}

TEST(ContactForces, ABoxOnAnInclineAboveTheFrictionAngleSlidesAtTheClosedFormAcceleration) {
  for (const auto& [deg, mu] : {std::pair{30.0, 0.2}, std::pair{45.0, 0.5}, std::pair{60.0, 0.0}}) {
    Incline in(deg, mu);
    const ForceResult r = solve_contact_forces(in.bodies, in.contacts, Vec2(0.0, -kG), kStep);
    ASSERT_TRUE(r.converged) << deg;
    const double expected = kG * (std::sin(in.theta) - mu * std::cos(in.theta));
    EXPECT_NEAR(r.acceleration[1].dot(in.down_slope), expected, 1e-9 * kG) << deg;
    EXPECT_NEAR(r.acceleration[1].dot(in.up), 0.0, 1e-9 * kG) << deg;
    EXPECT_LE(std::abs(r.angular_acceleration[1]) * in.w, 1e-9 * kG) << deg;
    for (const ForceContact& c : in.contacts) {
      EXPECT_NEAR(std::abs(c.force.y()), mu * c.force.x(), 1e-9 * in.mass * kG) << deg;
    }
  }
}

TEST(ContactForces, KineticFrictionSlowsASlidingBoxAndStopsItWithoutReversingIt) {
  const double mass = 1.0, w = 0.1, hh = 0.1, mu = 0.5;
  for (const double speed : {1.0, 1e-3}) {
    std::vector<ForceBody> bodies{fixed_floor(), box(mass, w, hh, Vec2(0.0, hh))};
    bodies[1].velocity = Vec2(speed, 0.0);
    std::vector<ForceContact> contacts = corners_on_floor(1, bodies[1], Vec2::UnitY(), w, hh, mu);
    const ForceResult r = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep);
    ASSERT_TRUE(r.converged) << speed;
    const double end_speed = speed + r.acceleration[1].x() * kStep;
    if (speed > mu * kG * kStep) {
      // Sliding the whole step: a = −μg exactly.
      EXPECT_NEAR(r.acceleration[1].x(), -mu * kG, 1e-9 * kG);
    } else {
      // Friction could stop it within the step: it ends at rest, not sliding backwards.
      EXPECT_NEAR(end_speed, 0.0, 1e-9 * kG * kStep);
    }
    EXPECT_NEAR(r.acceleration[1].y(), 0.0, 1e-9 * kG);
  }
}

TEST(ContactForces, AGapTheStepDoesNotCloseGetsNoForceAndOneItWouldCrossIsClosedExactly) {
  const double mass = 1.0, w = 0.1, hh = 0.1, speed = 0.1;
  // The step closes speed·h + ½gh² = 1.049e-4 m of the gap.
  const double closing = speed * kStep + 0.5 * kG * kStep * kStep;
  for (const double gap : {1e-3, 5e-5}) {
    std::vector<ForceBody> bodies{fixed_floor(), box(mass, w, hh, Vec2(0.0, hh + gap))};
    bodies[1].velocity = Vec2(0.0, -speed);
    std::vector<ForceContact> contacts = corners_on_floor(1, bodies[1], Vec2::UnitY(), w, hh, 0.3);
    for (ForceContact& c : contacts)
      c.gap = gap;
    const ForceResult r = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep);
    ASSERT_TRUE(r.converged) << gap;
    const BodyState end =
        driven_flight(state_of(bodies[1]), r.acceleration[1], r.angular_acceleration[1], kStep);
    const double end_gap = end.position.y() - hh;
    if (gap > closing) {
      EXPECT_EQ(contacts[0].force.x(), 0.0);
      EXPECT_EQ(contacts[1].force.x(), 0.0);
      EXPECT_EQ(r.acceleration[1], Vec2(0.0, -kG));
    } else {
      // The contacts push just enough to end the step touching (the least force that keeps
      // the gap open: complementarity), still moving down, never past the floor.
      EXPECT_NEAR(end_gap, 0.0, 1e-9 * gap);
      EXPECT_GT(contacts[0].force.x(), 0.0);
    }
  }
}

TEST(ContactForces, AFarGapDoesNotLoosenTheToleranceOfTheContactsThatRest) {
  // A third contact of the resting box whose gap is wide asks for nothing, however large the
  // approach it allows (2·gap/h); it must not set the scale the others converge to.
  const double mass = 3.0, w = 0.2, hh = 0.1;
  const std::vector<ForceBody> bodies{fixed_floor(), box(mass, w, hh, Vec2(0.0, hh))};
  std::vector<ForceContact> contacts = corners_on_floor(1, bodies[1], Vec2::UnitY(), w, hh, 0.5);
  ForceContact far = contacts[0];
  far.point = bodies[1].position + Vec2(0.0, hh);
  far.normal = -Vec2::UnitY();
  far.gap = 10.0;  // a ceiling 10 m above the box's top
  contacts.push_back(far);
  const ForceResult r = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(contacts[2].force, Vec2::Zero());
  EXPECT_NEAR(contacts[0].force.x() + contacts[1].force.x(), mass * kG, 1e-9 * mass * kG);
  EXPECT_LE(r.acceleration[1].norm(), 1e-9 * kG);
}

TEST(ContactForces, AStackCarriesTheWeightAboveEachLayerAndAWarmStartConvergesAtOnce) {
  const double mass = 1.5, w = 0.2, hh = 0.1;
  const std::size_t layers = 6;
  std::vector<ForceBody> bodies{fixed_floor()};
  std::vector<ForceContact> contacts;
  for (std::size_t k = 0; k < layers; ++k) {
    bodies.push_back(box(mass, w, hh, Vec2(0.0, static_cast<double>(2 * k + 1) * hh)));
    std::vector<ForceContact> row =
        corners_on_floor(bodies.size() - 1, bodies.back(), Vec2::UnitY(), w, hh, 0.6);
    for (ForceContact& c : row)
      c.body_b = k == 0 ? 0 : bodies.size() - 2;
    contacts.insert(contacts.end(), row.begin(), row.end());
  }
  // Cold, Gauss-Seidel carries the top's weight down one layer per sweep or so, and the
  // friction pairs under each box (statically indeterminate) settle slowly: this stack takes
  // about 3,700 sweeps to converge from zero forces. Warm starts spread that over steps.
  ForceSettings settings;
  settings.max_sweeps = 10000;
  const ForceResult cold = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep, settings);
  ASSERT_TRUE(cold.converged) << cold.residual;
  for (std::size_t k = 0; k < layers; ++k) {
    const double carried = contacts[2 * k].force.x() + contacts[2 * k + 1].force.x();
    EXPECT_NEAR(carried, static_cast<double>(layers - k) * mass * kG, 1e-6 * 6 * mass * kG) << k;
    EXPECT_LE(cold.acceleration[k + 1].norm(), 1e-6 * kG) << k;
  }
  // The next step of the same stack starts from these forces and has nothing left to do.
  const ForceResult warm = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep, settings);
  ASSERT_TRUE(warm.converged);
  EXPECT_LE(warm.sweeps, 2);
  EXPECT_LT(warm.sweeps, cold.sweeps);
}

TEST(ContactForces, ContactsNoForceCanMoveStayAtZeroAndTheResultIsReproducible) {
  const std::vector<ForceBody> bodies{fixed_floor(), fixed_floor(),
                                      box(1.0, 0.1, 0.1, Vec2(0, 0.1))};
  std::vector<ForceContact> contacts = corners_on_floor(2, bodies[2], Vec2::UnitY(), 0.1, 0.1, 0.4);
  ForceContact between_fixed;
  between_fixed.body_a = 1;
  between_fixed.body_b = 0;
  between_fixed.force = Vec2(5.0, 1.0);  // a stale warm start
  contacts.push_back(between_fixed);
  std::vector<ForceContact> again = contacts;
  const ForceResult r = solve_contact_forces(bodies, contacts, Vec2(0.0, -kG), kStep);
  const ForceResult r2 = solve_contact_forces(bodies, again, Vec2(0.0, -kG), kStep);
  EXPECT_EQ(contacts[2].force, Vec2::Zero());
  for (std::size_t i = 0; i < contacts.size(); ++i)
    EXPECT_EQ(contacts[i].force, again[i].force);
  EXPECT_EQ(r.acceleration, r2.acceleration);
  EXPECT_EQ(r.sweeps, r2.sweeps);
}

}  // namespace
}  // namespace rugosim
