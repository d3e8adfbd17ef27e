#include "engine/geometry/obb.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

constexpr double kPi = std::numbers::pi;

// Whether u is a unit vector parallel to v (either sign).
void expect_parallel(const Vec2& u, const Vec2& v, double tol) {
  EXPECT_NEAR(u.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(cross(u, v.normalized())), 0.0, tol)
      << u.transpose() << " vs " << v.transpose();
}

void expect_right_handed_frame(const PrincipalAxes& axes) {
  EXPECT_NEAR(axes.major.norm(), 1.0, 1e-12);
  EXPECT_NEAR(axes.minor.norm(), 1.0, 1e-12);
  EXPECT_NEAR(axes.major.dot(axes.minor), 0.0, 1e-12);
  EXPECT_NEAR(cross(axes.major, axes.minor), 1.0, 1e-12);
}

TEST(ObbPrincipalAxes, ElongatedSetGivesItsDirection) {
  Rng rng(1);
  for (int c = 0; c < 200; ++c) {
    const double angle = rng.uniform(-kPi, kPi);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    const Vec2 centre(rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0));
    std::vector<Vec2> points;
    for (int i = 0; i < 50; ++i) {
      points.push_back(centre + rng.uniform(-1.0, 1.0) * dir +
                       rng.uniform(-1e-3, 1e-3) * perp(dir));
    }
    const PrincipalAxes axes = principal_axes(points);
    expect_right_handed_frame(axes);
    expect_parallel(axes.major, dir, 1e-2);
  }
}

// The closed form agrees with Eigen's symmetric eigensolver wherever the largest eigenvalue is
// well separated (otherwise every direction is nearly principal).
TEST(ObbPrincipalAxes, MatchesEigenSolver) {
  Rng rng(2);
  for (int c = 0; c < 500; ++c) {
    std::vector<Vec2> points(static_cast<std::size_t>(rng.uniform(2.0, 40.0)));
    const double sx = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const double sy = sx * rng.uniform(0.0, 2.0);
    const Transform2 place(rng.uniform(-kPi, kPi), Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5)));
    for (Vec2& p : points)
      p = place.apply(Vec2(sx * rng.uniform(-1.0, 1.0), sy * rng.uniform(-1.0, 1.0)));
    Vec2 mean = Vec2::Zero();
    for (const Vec2& p : points)
      mean += p;
    mean /= static_cast<double>(points.size());
    Mat2 cov = Mat2::Zero();
    for (const Vec2& p : points)
      cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat2> solver(cov);
    const Vec2 values = solver.eigenvalues();  // ascending
    const PrincipalAxes axes = principal_axes(points);
    expect_right_handed_frame(axes);
    if (values(1) - values(0) > 1e-6 * values(1)) {
      expect_parallel(axes.major, solver.eigenvectors().col(1), 1e-6);
    }
  }
}

TEST(ObbPrincipalAxes, DegenerateSets) {
  // All points equal: no spread at all; any frame will do, and it must be a valid one.
  const std::vector<Vec2> same(7, Vec2(3.0, -2.0));
  expect_right_handed_frame(principal_axes(same));
  expect_right_handed_frame(principal_axes(std::vector<Vec2>{Vec2(1.0, 1.0)}));
  // Collinear points: the line's direction, whatever it is (vertical included).
  for (const Vec2& dir : {Vec2(1, 0), Vec2(0, 1), Vec2(1, 1), Vec2(-3, 1), Vec2(1e-9, 1)}) {
    std::vector<Vec2> line;
    for (int i = 0; i < 5; ++i)
      line.push_back(Vec2(10.0, -4.0) + static_cast<double>(i * i) * dir);
    const PrincipalAxes axes = principal_axes(line);
    expect_right_handed_frame(axes);
    expect_parallel(axes.major, dir, 1e-12);
  }
  // Isotropic spread (the corners of a square): every direction is principal.
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  expect_right_handed_frame(principal_axes(square));
  EXPECT_THROW(principal_axes(std::vector<Vec2>{}), std::invalid_argument);
  EXPECT_THROW(bound_along(std::vector<Vec2>{}, Vec2::UnitX()), std::invalid_argument);
}

// bound_along contains every point and touches the set on all four sides.
TEST(Obb, BoundAlongIsTheTightBoxOnTheGivenAxes) {
  Rng rng(3);
  for (int c = 0; c < 300; ++c) {
    const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const Vec2 offset = scale * Vec2(rng.uniform(-50, 50), rng.uniform(-50, 50));
    std::vector<Vec2> points(static_cast<std::size_t>(rng.uniform(1.0, 30.0)));
    for (Vec2& p : points)
      p = offset + scale * Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double angle = rng.uniform(-kPi, kPi);
    const Vec2 axis(std::cos(angle), std::sin(angle));
    const Obb box = bound_along(points, axis);
    EXPECT_EQ(box.axis_x, axis);
    EXPECT_NEAR(box.axis_y.dot(axis), 0.0, 1e-15);
    const double slack = 1e-12 * scale * 60.0;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const Vec2& p : points) {
      EXPECT_TRUE(box.contains(p, slack));
      const Vec2 d = p - box.center;
      lo_x = std::min(lo_x, d.dot(box.axis_x));
      hi_x = std::max(hi_x, d.dot(box.axis_x));
      lo_y = std::min(lo_y, d.dot(box.axis_y));
      hi_y = std::max(hi_y, d.dot(box.axis_y));
    }
    EXPECT_NEAR(lo_x, -box.half_extents.x(), slack);
    EXPECT_NEAR(hi_x, box.half_extents.x(), slack);
    EXPECT_NEAR(lo_y, -box.half_extents.y(), slack);
    EXPECT_NEAR(hi_y, box.half_extents.y(), slack);
    // fit_obb is the same bound on the principal axes.
    const Obb fitted = fit_obb(points);
    EXPECT_EQ(fitted.axis_x, principal_axes(points).major);
  }
}

TEST(Obb, CornersAreCounterClockwiseAndSpanTheArea) {
  Obb box;
  box.center = Vec2(2.0, -1.0);
  box.axis_x = Vec2(std::cos(0.3), std::sin(0.3));
  box.axis_y = perp(box.axis_x);
  box.half_extents = Vec2(1.5, 0.25);
  const auto c = box.corners();
  double twice_area = 0.0;
  for (std::size_t i = 0; i < 4; ++i)
    twice_area += cross(c[i], c[(i + 1) % 4]);
  EXPECT_NEAR(0.5 * twice_area, box.area(), 1e-12);
  EXPECT_NEAR(box.area(), 1.5, 1e-15);
  for (const Vec2& corner : c) {
    EXPECT_TRUE(box.contains(corner, 1e-12));
    EXPECT_FALSE(box.contains(corner + 1e-6 * (corner - box.center), 0.0));
  }
  EXPECT_TRUE(box.contains(box.center));
}

// A box at a random place and angle, with half extents up to 2 (either may be 0).
Obb random_box(Rng& rng) {
  Obb box;
  const double angle = rng.uniform(-kPi, kPi);
  box.center = Vec2(rng.uniform(-3, 3), rng.uniform(-3, 3));
  box.axis_x = Vec2(std::cos(angle), std::sin(angle));
  box.axis_y = perp(box.axis_x);
  box.half_extents = Vec2(rng.uniform(0, 2), rng.uniform(0, 2));
  return box;
}

// The fattened box holds every point within `margin` of the original box, and no more along
// its axes.
TEST(Obb, FattenedHoldsTheMarginNeighbourhood) {
  Rng rng(4);
  for (int c = 0; c < 200; ++c) {
    const Obb box = random_box(rng);
    const double margin = rng.uniform(0.0, 0.5);
    const Obb fat = box.fattened(margin);
    EXPECT_EQ(fat.center, box.center);
    for (const Vec2& corner : box.corners()) {
      for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * kPi * k / 16.0;
        EXPECT_TRUE(fat.contains(corner + margin * Vec2(std::cos(a), std::sin(a)), 1e-12));
      }
    }
    EXPECT_FALSE(
        fat.contains(box.center + (box.half_extents.x() + margin + 1e-6) * box.axis_x, 0.0));
  }
}

TEST(Obb, TransformedPlacesTheBoxRigidly) {
  Rng rng(5);
  for (int c = 0; c < 200; ++c) {
    const Obb box = random_box(rng);
    const Transform2 x(rng.uniform(-kPi, kPi), Vec2(rng.uniform(-9, 9), rng.uniform(-9, 9)));
    const Obb placed = box.transformed(x);
    EXPECT_EQ(placed.half_extents, box.half_extents);
    const auto before = box.corners();
    const auto after = placed.corners();
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR((after[i] - x.apply(before[i])).norm(), 0.0, 1e-12);
    for (int k = 0; k < 20; ++k) {
      const Vec2 p(rng.uniform(-6, 6), rng.uniform(-6, 6));
      const Vec2 d = p - box.center;
      // Skip points within rounding of the boundary.
      if (std::abs(std::abs(d.dot(box.axis_x)) - box.half_extents.x()) < 1e-9) continue;
      if (std::abs(std::abs(d.dot(box.axis_y)) - box.half_extents.y()) < 1e-9) continue;
      EXPECT_EQ(placed.contains(x.apply(p)), box.contains(p));
    }
  }
}

}  // namespace
}  // namespace rugosim
