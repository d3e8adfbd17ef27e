#include "engine/dynamics/rigid_body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/dynamics/free_flight.h"
#include "engine/dynamics/material.h"
#include "engine/geometry/mass_properties.h"
#include "engine/geometry/shapes.h"
#include "support/random_curves.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::scientific;

using testing::extent_of;
using testing::random_control_polygon;

// A w × h box (exactly the rectangle: n >= 12 keeps sharp corners) whose user frame has its
// origin at the box's lower-left corner, so that the centroid is not at the user's origin.
RigidBodyDesc box_desc(double w, double h, double density) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(w, h, 16);
  for (Vec2& p : desc.control_points)
    p += Vec2(0.5 * w, 0.5 * h);
  desc.material.density = density;
  return desc;
}

// Message of the std::invalid_argument the constructor throws, or "" when it does not.
std::string construction_error(const RigidBodyDesc& desc) {
  try {
    RigidBody body(desc);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::vector<double> random_sigma(Rng& rng, std::size_t n, double scale) {
  std::vector<double> sigma(n);
  for (double& s : sigma)
    s = scale * rng.uniform(0.0, 0.01);
  return sigma;
}

TEST(Material, DefaultsAreValidAndEachBadValueIsNamed) {
  EXPECT_EQ(Material{}.validate(), "");
  Material m;
  m.density = 0.0;
  EXPECT_NE(m.validate().find("density"), std::string::npos) << m.validate();
  m = Material{};
  m.restitution = 1.5;
  EXPECT_NE(m.validate().find("restitution must be in [0, 1]"), std::string::npos);
  m = Material{};
  m.restitution = 0.6;
  m.restitution_max = 0.4;
  EXPECT_NE(m.validate().find("restitution_max"), std::string::npos) << m.validate();
  m = Material{};
  m.lambda_min = -1e-3;
  EXPECT_NE(m.validate().find("lambda_min"), std::string::npos);
  m = Material{};
  m.density = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(m.validate(), "");
}

TEST(RigidBody, BoxMassAndInertiaAreClosedForm) {
  const double w = 0.8, h = 0.3, density = 2500.0;
  const RigidBody body(box_desc(w, h, density));
  const double mass = density * w * h;
  const double inertia = mass * (w * w + h * h) / 12.0;
  EXPECT_NEAR(body.area(), w * h, 1e-14);
  EXPECT_NEAR(body.mass(), mass, 1e-12 * mass);
  EXPECT_NEAR(body.inertia(), inertia, 1e-12 * inertia);
  EXPECT_NEAR(body.inverse_mass(), 1.0 / mass, 1e-12 / mass);
  EXPECT_NEAR(body.inverse_inertia(), 1.0 / inertia, 1e-12 / inertia);
  // The box's centre, in the user frame whose origin is the lower-left corner.
  EXPECT_NEAR((body.centroid_offset() - Vec2(0.5 * w, 0.5 * h)).norm(), 0.0, 1e-15);
  // The corner is the farthest point of a sharp box.
  EXPECT_NEAR(body.bounding_radius(), 0.5 * std::hypot(w, h), 1e-15);
}

// The same boundary given clockwise, with σ carried by the same pieces of curve, is the same
// body; σ stays with its segment through the reversal.
TEST(RigidBody, ClockwiseInputGivesTheSameBodyAndSigmaFollowsItsSegments) {
  Rng rng(601);
  for (int c = 0; c < 60; ++c) {
    const std::size_t n = 4 + static_cast<std::size_t>(rng.uniform(0.0, 60.0));
    RigidBodyDesc ccw;
    ccw.control_points = random_control_polygon(rng, n);
    const double scale = extent_of(ccw.control_points) + ccw.control_points.front().norm();
    ccw.sigma = random_sigma(rng, n, extent_of(ccw.control_points));
    ccw.q = 0.8;
    ccw.position = Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5));
    ccw.angle = rng.uniform(-10, 10);

    // Input Q_i = P_{n−1−i}: segment i of Q runs through P's segment n−2−i backwards.
    RigidBodyDesc cw = ccw;
    std::reverse(cw.control_points.begin(), cw.control_points.end());
    for (std::size_t i = 0; i < n; ++i)
      cw.sigma[i] = ccw.sigma[(2 * n - 2 - i) % n];

    const RigidBody a(ccw), b(cw);
    EXPECT_FALSE(a.input_reversed());
    EXPECT_TRUE(b.input_reversed());
    EXPECT_GT(signed_area(b.curve()), 0.0);
    EXPECT_NEAR(b.mass(), a.mass(), 1e-12 * a.mass());
    EXPECT_NEAR(b.inertia(), a.inertia(), 1e-12 * a.inertia());
    EXPECT_LE((b.centroid_offset() - a.centroid_offset()).norm(), 1e-12 * scale);
    EXPECT_LE((b.state().position - a.state().position).norm(), 1e-12 * scale);

    // Every stored segment of b lies where a segment of a lies, with the same tolerance.
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 mid = b.curve().point(k, 0.5);
      std::size_t nearest = 0;
      for (std::size_t j = 1; j < n; ++j) {
        if ((a.curve().point(j, 0.5) - mid).norm() < (a.curve().point(nearest, 0.5) - mid).norm())
          nearest = j;
      }
      EXPECT_LE((a.curve().point(nearest, 0.5) - mid).norm(), 1e-12 * scale);
      EXPECT_EQ(b.shape().tolerances().segment_tolerance(k),
                a.shape().tolerances().segment_tolerance(nearest))
          << "case " << c << " segment " << k;
      // The stored segment names its input segment: same σ, same place.
      EXPECT_EQ(b.shape().tolerances().segment_tolerance(k), cw.q * cw.sigma[b.input_segment(k)]);
      const PeriodicBSpline input(cw.control_points);
      for (double t : {0.0, 0.3, 0.5, 0.9}) {
        const CurveParam in = b.to_input_param({k, t});
        EXPECT_GE(in.t, 0.0);
        EXPECT_LT(in.t, 1.0);
        EXPECT_LE(
            (b.curve().point(k, t) + b.centroid_offset() - input.point(in.segment, in.t)).norm(),
            1e-12 * scale);
      }
    }
  }
}

TEST(RigidBody, RecentredCurveHasItsCentroidAtTheOriginAndTheUserOriginRoundTrips) {
  Rng rng(602);
  for (int c = 0; c < 100; ++c) {
    const std::size_t n = 4 + static_cast<std::size_t>(rng.uniform(0.0, 200.0));
    RigidBodyDesc desc;
    desc.control_points = random_control_polygon(rng, n);
    const double scale = extent_of(desc.control_points) + desc.control_points.front().norm();
    desc.position = scale * Vec2(rng.uniform(-3, 3), rng.uniform(-3, 3));
    desc.angle = rng.uniform(-20, 20);
    RigidBody body(desc);

    const MassProperties stored = compute_mass_properties(body.curve());
    EXPECT_LE(stored.centroid.norm(), 1e-12 * scale) << "case " << c;
    EXPECT_NEAR(stored.area, body.area(), 1e-12 * body.area());

    const double where = scale + desc.position.norm();
    EXPECT_LE((body.origin_position() - desc.position).norm(), 1e-13 * where);
    EXPECT_EQ(body.state().angle, desc.angle);
    // The user's control points land where the user's placement puts them.
    const Transform2 user(desc.angle, desc.position);
    for (std::size_t i = 0; i < n; i += 1 + n / 16) {
      EXPECT_LE(
          (body.world_point(body.curve().control_points()[i]) - user.apply(desc.control_points[i]))
              .norm(),
          1e-13 * where);
    }
    // Placing the origin again moves the centre of mass with it.
    const Vec2 origin = scale * Vec2(rng.uniform(-3, 3), rng.uniform(-3, 3));
    const double angle = rng.uniform(-20, 20);
    body.place_origin(origin, angle);
    EXPECT_LE((body.origin_position() - origin).norm(), 1e-13 * (scale + origin.norm()));
    EXPECT_LE((body.world_point(-body.centroid_offset()) - body.origin_position()).norm(),
              1e-13 * (scale + origin.norm()));
    EXPECT_LE((body.placement().translation() - body.state().position).norm(), 0.0);
  }
}

// Thickness, 2 × area / perimeter: r for a disk, about t for a thin plate, half the side of a
// square: never more than a convex body's least width.
TEST(RigidBody, ThicknessIsTwiceAreaOverPerimeter) {
  auto body_of = [](std::vector<Vec2> points) {
    RigidBodyDesc d;
    d.control_points = std::move(points);
    return RigidBody(d);
  };
  EXPECT_NEAR(body_of(circle_control_points(0.2, 64)).thickness(), 0.2, 1e-6);
  EXPECT_NEAR(body_of(box_control_points(1.0, 0.001, 16)).thickness(), 2.0 * 0.001 / 2.002, 1e-12);
  EXPECT_NEAR(body_of(box_control_points(0.4, 0.4, 16)).thickness(), 0.2, 1e-12);
  const RigidBody spinning = [&] {
    RigidBodyDesc d;
    d.control_points = box_control_points(0.4, 0.2, 16);
    d.velocity = Vec2(3.0, 4.0);
    d.angular_velocity = -2.0;
    return RigidBody(d);
  }();
  EXPECT_NEAR(spinning.boundary_speed(), 5.0 + 2.0 * spinning.bounding_radius(), 1e-12);
}

TEST(RigidBody, BoundingRadiusHoldsTheCurve) {
  Rng rng(603);
  for (int c = 0; c < 30; ++c) {
    RigidBodyDesc desc;
    desc.control_points = random_control_polygon(rng, 5 + static_cast<std::size_t>(c));
    const RigidBody body(desc);
    double farthest = 0.0;
    for (std::size_t j = 0; j < body.curve().size(); ++j) {
      for (int s = 0; s <= 20; ++s)
        farthest = std::max(farthest, body.curve().point(j, s / 20.0).norm());
    }
    EXPECT_LE(farthest, body.bounding_radius() * (1.0 + 1e-14));
  }
}

// velocity_at is the time derivative of a material point's world position.
TEST(RigidBody, VelocityAtMatchesFiniteDifferencesOfWorldPointsInFreeFlight) {
  RigidBodyDesc desc;
  desc.control_points = blob_control_points(0.4, 0.5, 24, 7);
  desc.velocity = Vec2(1.5, 2.0);
  desc.angular_velocity = -3.0;
  desc.position = Vec2(0.3, -0.2);
  desc.angle = 0.7;
  const Vec2 gravity(0.0, -9.81);
  RigidBody body(desc);
  const double h = 1e-4;  // s
  double worst = 0.0;
  for (double t : {0.0, 0.13, 0.5, 1.1}) {
    RigidBody now = body, before = body, after = body;
    advance_free_flight(now, gravity, t);
    advance_free_flight(before, gravity, t - h);
    advance_free_flight(after, gravity, t + h);
    for (const Vec2& p : body.curve().control_points()) {
      const Vec2 fd = (after.world_point(p) - before.world_point(p)) / (2.0 * h);
      const Vec2 v = now.velocity_at(now.world_point(p));
      // Central differences err by |ω|³·r·h²/6 ≈ 1e-7 m/s here, rounding by about 1e-12/h.
      worst = std::max(worst, (fd - v).norm());
      EXPECT_LE((fd - v).norm(), 1e-6) << "t " << t;
    }
  }
  RecordProperty("worst_velocity_error_m_per_s", scientific(worst));
}

// ½mv² + ½Iω² against the integral of ½ρ|v(p)|² over the box, by the midpoint rule.
TEST(RigidBody, KineticEnergyIsTheIntegralOfPointwiseKineticEnergy) {
  const double w = 0.6, h = 0.2, density = 800.0;
  RigidBodyDesc desc = box_desc(w, h, density);
  desc.velocity = Vec2(3.0, -4.0);
  desc.angular_velocity = 2.5;
  desc.angle = 0.4;
  desc.position = Vec2(1.0, 2.0);
  const RigidBody body(desc);
  const double expected = 0.5 * body.mass() * 25.0 + 0.5 * body.inertia() * 2.5 * 2.5;
  EXPECT_NEAR(body.kinetic_energy(), expected, 1e-12 * expected);

  const int nx = 600, ny = 200;
  double integral = 0.0;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      // Cell centres in the user frame (box from (0, 0) to (w, h)).
      const Vec2 user((i + 0.5) * w / nx, (j + 0.5) * h / ny);
      const Vec2 p = body.world_point(user - body.centroid_offset());
      integral += 0.5 * density * body.velocity_at(p).squaredNorm() * (w / nx) * (h / ny);
    }
  }
  // The midpoint rule errs by O(cell²) on this quadratic integrand: about 1e-7 relative.
  EXPECT_NEAR(integral, expected, 1e-6 * expected);
}

TEST(RigidBody, FixedBodyHasZeroInverseMassAndDoesNotMove) {
  RigidBodyDesc desc = box_desc(2.0, 0.4, 1000.0);
  desc.fixed = true;
  desc.position = Vec2(-1.0, -0.2);
  RigidBody body(desc);
  EXPECT_TRUE(body.fixed());
  EXPECT_EQ(body.inverse_mass(), 0.0);
  EXPECT_EQ(body.inverse_inertia(), 0.0);
  EXPECT_NEAR(body.mass(), 1000.0 * 0.8, 1e-9);  // reported all the same
  EXPECT_EQ(body.kinetic_energy(), 0.0);

  const BodyState before = body.state();
  advance_free_flight(body, Vec2(0.0, -9.81), 3.0);
  EXPECT_EQ(body.state().position, before.position);
  EXPECT_EQ(body.state().angle, before.angle);
  EXPECT_EQ(body.state().velocity, Vec2::Zero());
  EXPECT_EQ(body.state().angular_velocity, 0.0);

  BodyState moving = before;
  moving.velocity = Vec2(1.0, 0.0);
  EXPECT_THROW(body.set_state(moving), std::invalid_argument);
  desc.angular_velocity = 1.0;
  EXPECT_NE(construction_error(desc).find("fixed body cannot move"), std::string::npos);
}

TEST(RigidBody, CopiesShareTheirCollisionShape) {
  const RigidBody a(box_desc(1.0, 1.0, 1.0));
  RigidBody b = a;
  b.place_origin(Vec2(5.0, 0.0), 1.0);
  EXPECT_EQ(a.shared_shape().get(), b.shared_shape().get());
  EXPECT_NE(a.state().position, b.state().position);
}

TEST(RigidBody, InvalidInputThrowsWithTheReason) {
  RigidBodyDesc bowtie;  // a figure-eight: the B-spline crosses itself at the origin
  bowtie.control_points = {{1, 1}, {-1, -1}, {-1, 1}, {1, -1}};
  std::string why = construction_error(bowtie);
  EXPECT_NE(why.find("invalid boundary"), std::string::npos) << why;
  EXPECT_NE(why.find("cross"), std::string::npos) << why;

  RigidBodyDesc line;
  line.control_points = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  why = construction_error(line);
  EXPECT_NE(why.find("invalid boundary"), std::string::npos) << why;

  RigidBodyDesc few;
  few.control_points = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_NE(construction_error(few), "");

  RigidBodyDesc ok = box_desc(1.0, 0.5, 1.0);
  EXPECT_EQ(construction_error(ok), "");

  RigidBodyDesc bad = ok;
  bad.sigma = {0.1, 0.2};
  why = construction_error(bad);
  EXPECT_NE(why.find("sigma has 2 values"), std::string::npos) << why;

  bad = ok;
  bad.sigma.assign(ok.control_points.size(), 0.001);
  bad.sigma[3] = -0.001;
  EXPECT_NE(construction_error(bad), "");

  bad = ok;
  bad.q = 0.0;
  EXPECT_NE(construction_error(bad), "");

  bad = ok;
  bad.material.density = -1.0;
  why = construction_error(bad);
  EXPECT_NE(why.find("material: density"), std::string::npos) << why;

  bad = ok;
  bad.velocity = Vec2(std::numeric_limits<double>::infinity(), 0.0);
  EXPECT_NE(construction_error(bad), "");
}

TEST(RigidBody, FrictionCoefficientFollowsTheToleranceAndTheMaterialThreshold) {
  RigidBodyDesc desc = box_desc(1.0, 0.5, 1.0);
  const std::size_t n = desc.control_points.size();
  desc.sigma.assign(n, 0.004);  // λ = 0.9 · 0.004 = 0.0036 m everywhere
  desc.material.lambda_min = 0.001;
  const RigidBody body(desc);
  for (std::size_t k = 0; k < n; ++k) {
    for (double t : {0.0, 0.25, 0.5, 0.99})
      EXPECT_NEAR(body.friction_coefficient(k, t, 100.0), 100.0 * (0.0036 - 0.001), 1e-12);
  }
  desc.material.lambda_min = 0.005;  // smoother than the threshold: frictionless
  EXPECT_EQ(RigidBody(desc).friction_coefficient(2, 0.5, 100.0), 0.0);

  // A rough and a smooth half: μ at a segment's midpoint uses that segment's own λ.
  for (std::size_t j = 0; j < n; ++j)
    desc.sigma[j] = j < n / 2 ? 0.01 : 0.0;
  desc.material.lambda_min = 0.0;
  const RigidBody mixed(desc);
  for (std::size_t k = 0; k < n; ++k) {
    const double lambda = 0.9 * desc.sigma[mixed.input_segment(k)];
    EXPECT_NEAR(mixed.friction_coefficient(k, 0.5, 50.0), 50.0 * lambda, 1e-12);
  }
}

}  // namespace
}  // namespace rugosim
