#include "engine/geometry/shapes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/boundary_validity.h"
#include "engine/geometry/mass_properties.h"
#include "engine/geometry/orientation.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {
namespace {

TEST(Shapes, CircleKnotsLieOnTheCircleAndTheCurveHugsIt) {
  for (std::size_t n : {4u, 8u, 32u, 256u}) {
    const PeriodicBSpline curve(circle_control_points(2.0, n));
    double worst = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_NEAR(curve.point(j, 0.0).norm(), 2.0, 1e-14);
      for (int k = 0; k <= 20; ++k)
        worst = std::max(worst, std::abs(curve.point(j, k / 20.0).norm() - 2.0));
    }
    // The dip inside the circle between knots falls like h^4, h = 2π/n (measured: 0.0046 h^4 at n =
    // 4, 0.0026 h^4 from n = 32 on, that is 3.9e-6 r at n = 32).
    const double step = 2.0 * std::numbers::pi / static_cast<double>(n);
    EXPECT_LE(worst / 2.0, 0.005 * std::pow(step, 4)) << n;
  }
}

TEST(Shapes, EllipseIsTheScaledCircle) {
  const auto circle = circle_control_points(1.0, 40);
  const auto ellipse = ellipse_control_points(3.0, 0.5, 40);
  for (std::size_t i = 0; i < 40; ++i) {
    EXPECT_NEAR(ellipse[i].x(), 3.0 * circle[i].x(), 1e-14);
    EXPECT_NEAR(ellipse[i].y(), 0.5 * circle[i].y(), 1e-14);
  }
}

TEST(Shapes, SharpBoxIsExactlyTheRectangle) {
  for (std::size_t n : {12u, 13u, 32u, 101u}) {
    const auto points = box_control_points(6.0, 0.4, n);
    ASSERT_EQ(points.size(), n);
    const PeriodicBSpline curve(points);
    for (std::size_t j = 0; j < n; ++j) {
      for (int k = 0; k <= 10; ++k) {
        const Vec2 p = curve.point(j, k / 10.0);
        // On the rectangle's outline: one coordinate at its extreme, the other inside.
        const double dx = std::abs(std::abs(p.x()) - 3.0), dy = std::abs(std::abs(p.y()) - 0.2);
        EXPECT_LE(std::min(dx, dy), 1e-15) << n << " " << j;
        EXPECT_LE(std::abs(p.x()), 3.0 + 1e-15);
        EXPECT_LE(std::abs(p.y()), 0.2 + 1e-15);
      }
    }
  }
}

TEST(Shapes, CoarseBoxIsRoundedInsideTheRectangle) {
  for (std::size_t n = 4; n < kSharpBoxMinSegments; ++n) {
    const PeriodicBSpline curve(box_control_points(2.0, 1.0, n));
    for (std::size_t j = 0; j < n; ++j) {
      const Vec2 p = curve.point(j, 0.3);
      EXPECT_LE(std::abs(p.x()), 1.0);
      EXPECT_LE(std::abs(p.y()), 0.5);
    }
  }
}

TEST(Shapes, BlobIsSeededBoundedAndCounterClockwise) {
  const auto a = blob_control_points(1.0, 0.6, 48, 3);
  EXPECT_EQ(a, blob_control_points(1.0, 0.6, 48, 3));
  EXPECT_NE(a, blob_control_points(1.0, 0.6, 48, 4));
  const double scale = circle_control_radius(1.0, 48);
  double twice_area = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_GE(a[i].norm(), scale * 0.4 - 1e-12);
    EXPECT_LE(a[i].norm(), scale * 1.6 + 1e-12);
    twice_area += cross(a[i], a[(i + 1) % a.size()]);
  }
  EXPECT_GT(twice_area, 0.0);
  // Irregularity 0 is the circle.
  const auto round = blob_control_points(1.0, 0.0, 48, 3);
  const auto circle = circle_control_points(1.0, 48);
  for (std::size_t i = 0; i < 48; ++i)
    EXPECT_NEAR((round[i] - circle[i]).norm(), 0.0, 1e-14);
}

TEST(Shapes, EveryGeneratedShapeIsAValidCounterClockwiseBoundary) {
  Rng rng(31);
  for (int c = 0; c < 300; ++c) {
    const auto n = static_cast<std::size_t>(
        std::lround(std::exp(rng.uniform(std::log(4.0), std::log(1024.0)))));
    const double size = std::pow(10.0, rng.uniform(-3.0, 3.0));
    const double irregularity = rng.uniform(0.0, kMaxBlobIrregularity);
    for (const auto& points :
         {circle_control_points(size, n), ellipse_control_points(size, 0.1 * size, n),
          box_control_points(size, 0.05 * size, n),
          blob_control_points(size, irregularity, n, rng.next_u64())}) {
      const PeriodicBSpline curve(points);
      const ValidityReport report = check_boundary(curve);
      ASSERT_TRUE(report.valid) << "case " << c << " n " << n << ": " << report.reason;
      EXPECT_TRUE(is_counter_clockwise(curve));
    }
  }
}

TEST(Shapes, SplineCircleApproachesTheDiskAreaAndInertia) {
  // Area -> πr² and inertia -> ½ m r², with the error falling like n^-4.
  double previous_error = 1.0;
  for (std::size_t n : {8u, 32u, 128u, 512u}) {
    const MassProperties props =
        compute_mass_properties(PeriodicBSpline(circle_control_points(0.5, n)));
    const double disk_area = std::numbers::pi * 0.25;
    const double area_error = std::abs(props.area / disk_area - 1.0);
    const double inertia_error =
        std::abs(props.inertia(7.0) / (0.5 * props.mass(7.0) * 0.25) - 1.0);
    EXPECT_LE(area_error, 6.0 / std::pow(static_cast<double>(n), 4)) << n;
    EXPECT_LE(inertia_error, 12.0 / std::pow(static_cast<double>(n), 4)) << n;
    EXPECT_LE(props.centroid.norm(), 1e-15);
    EXPECT_LT(area_error, previous_error / 100.0);
    previous_error = area_error;
  }
}

TEST(Shapes, RejectBadParameters) {
  EXPECT_THROW(circle_control_points(1.0, 3), std::invalid_argument);
  EXPECT_THROW(circle_control_points(0.0, 8), std::invalid_argument);
  EXPECT_THROW(ellipse_control_points(1.0, -1.0, 8), std::invalid_argument);
  EXPECT_THROW(box_control_points(NAN, 1.0, 8), std::invalid_argument);
  EXPECT_THROW(blob_control_points(1.0, 0.95, 8, 0), std::invalid_argument);
  EXPECT_THROW(blob_control_points(1.0, -0.1, 8, 0), std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
