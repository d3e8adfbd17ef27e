#include "engine/geometry/shapes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

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

// A sharp polygon is exactly its edges: every curve point lies on one of them (brute force
// over the edges), each corner is reached, and the area is the polygon's (shoelace formula).
TEST(Shapes, SharpPolygonIsExactlyItsEdges) {
  const std::vector<Vec2> wedge = {Vec2(-0.3, 0.0), Vec2(0.3, 0.0), Vec2(0.05, 0.25),
                                   Vec2(0.0, 0.1)};
  for (std::size_t n : {12u, 13u, 40u}) {
    const PeriodicBSpline curve(polygon_control_points(wedge, {}, n));
    ASSERT_EQ(curve.size(), n);
    std::vector<double> nearest_corner(wedge.size(), 1e9);
    for (std::size_t j = 0; j < n; ++j) {
      for (int k = 0; k <= 16; ++k) {
        const Vec2 p = curve.point(j, k / 16.0);
        double off = 1e9;
        for (std::size_t e = 0; e < wedge.size(); ++e) {
          const Vec2 a = wedge[e], b = wedge[(e + 1) % wedge.size()];
          const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          off = std::min(off, (a + t * (b - a) - p).norm());
          nearest_corner[e] = std::min(nearest_corner[e], (p - a).norm());
        }
        EXPECT_LE(off, 1e-15) << n << " " << j << " " << k;
      }
    }
    for (const double d : nearest_corner)
      EXPECT_LE(d, 1e-15) << "every corner is on the curve, sharp";
    double shoelace = 0.0;
    for (std::size_t e = 0; e < wedge.size(); ++e)
      shoelace += 0.5 * cross(wedge[e], wedge[(e + 1) % wedge.size()]);
    EXPECT_NEAR(std::abs(signed_area(curve)), std::abs(shoelace), 1e-14);
    EXPECT_TRUE(check_boundary(curve).valid);
  }
  // The box is the four-corner polygon.
  const std::vector<Vec2> rectangle = {Vec2(-3.0, -0.2), Vec2(3.0, -0.2), Vec2(3.0, 0.2),
                                       Vec2(-3.0, 0.2)};
  for (std::size_t n : {12u, 31u})
    EXPECT_EQ(box_control_points(6.0, 0.4, n), polygon_control_points(rectangle, {}, n));
}

// A rounded corner stays inside the polygon and misses the corner by a share of its rounding;
// the other corners stay sharp.
TEST(Shapes, RoundedPolygonCornersTurnInsideWithinTheirRounding) {
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const std::vector<double> rounding = {0.0, 0.2, 0.0, 0.4};
  const PeriodicBSpline curve(polygon_control_points(square, rounding, 32));
  EXPECT_TRUE(check_boundary(curve).valid);
  std::vector<double> nearest(4, 1e9);
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (int k = 0; k <= 32; ++k) {
      const Vec2 p = curve.point(j, k / 32.0);
      EXPECT_GE(p.x(), -1e-15);
      EXPECT_LE(p.x(), 1 + 1e-15);
      EXPECT_GE(p.y(), -1e-15);
      EXPECT_LE(p.y(), 1 + 1e-15);
      for (std::size_t c = 0; c < 4; ++c)
        nearest[c] = std::min(nearest[c], (p - square[c]).norm());
    }
  }
  EXPECT_LE(nearest[0], 1e-15);
  EXPECT_LE(nearest[2], 1e-15);
  for (const std::size_t c : {1u, 3u}) {
    EXPECT_GT(nearest[c], 0.05 * rounding[c]) << c;
    EXPECT_LT(nearest[c], rounding[c]) << c;
  }
  EXPECT_GT(nearest[3], nearest[1]) << "more rounding, farther from the corner";
  EXPECT_THROW(polygon_control_points(square, std::vector<double>{0.0, 0.6, 0.0, 0.0}, 32),
               std::invalid_argument);
  EXPECT_THROW(polygon_control_points(square, std::vector<double>{0.1}, 32), std::invalid_argument);
  EXPECT_THROW(polygon_control_points(square, {}, 11), std::invalid_argument);
  EXPECT_THROW(polygon_control_points(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0)}, {}, 12),
               std::invalid_argument);
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
