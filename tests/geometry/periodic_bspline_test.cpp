#include "engine/geometry/periodic_bspline.h"

#include <stdexcept>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/subdivision.h"
#include "support/random_curves.h"

namespace rugosim {
namespace {

using testing::extent_of;
using testing::random_control_polygon;
using testing::random_segment_count;

constexpr int kCases = 300;

// The paper's eq. (1)-(2) literally: f_j(t) = [t^3 t^2 t 1] M C_j / 6.
Vec2 paper_matrix_point(const std::vector<Vec2>& c, std::size_t j, double t) {
  Eigen::Matrix4d m;
  m << -1, 3, -3, 1, 3, -6, 3, 0, -3, 0, 3, 0, 1, 4, 1, 0;
  const Eigen::RowVector4d powers(t * t * t, t * t, t, 1.0);
  const std::size_t n = c.size();
  Eigen::Matrix<double, 4, 2> cj;
  for (int k = 0; k < 4; ++k)
    cj.row(k) = c[(j + n - 1 + static_cast<std::size_t>(k)) % n];
  return (powers * m * cj / 6.0).transpose();
}

TEST(PeriodicBSpline, RejectsTooFewOrNonFinitePoints) {
  EXPECT_THROW(PeriodicBSpline({{0, 0}, {1, 0}, {0, 1}}), std::invalid_argument);
  EXPECT_THROW(PeriodicBSpline({{0, 0}, {1, 0}, {1, 1}, {0, std::nan("")}}), std::invalid_argument);
  EXPECT_NO_THROW(PeriodicBSpline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(PeriodicBSpline, MatchesThePaperBasisMatrix) {
  Rng rng(1);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const PeriodicBSpline curve(points);
    const double scale = extent_of(points) + points.front().norm();
    for (int k = 0; k < 8; ++k) {
      const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(curve.size()));
      const double t = rng.uniform();
      EXPECT_LE((curve.point(j, t) - paper_matrix_point(points, j, t)).norm(), 1e-13 * scale);
    }
  }
}

TEST(PeriodicBSpline, DerivativesMatchFiniteDifferences) {
  Rng rng(2);
  for (int c = 0; c < 50; ++c) {
    const PeriodicBSpline curve(random_control_polygon(rng, random_segment_count(rng, c)));
    const double h = 1e-5;
    for (int k = 0; k < 8; ++k) {
      const double u = rng.uniform(0.0, static_cast<double>(curve.size()));
      const Vec2 d1 = (curve.point_at(u + h) - curve.point_at(u - h)) / (2 * h);
      const Vec2 d2 = (curve.derivative_at(u + h) - curve.derivative_at(u - h)) / (2 * h);
      const double scale = curve.derivative_at(u).norm() + curve.second_derivative_at(u).norm() +
                           curve.hull_bounds().diagonal();
      EXPECT_LE((d1 - curve.derivative_at(u)).norm(), 1e-7 * scale);
      EXPECT_LE((d2 - curve.second_derivative_at(u)).norm(), 1e-7 * scale);
    }
  }
}

TEST(PeriodicBSpline, IsC2AtEveryJoint) {
  Rng rng(3);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const PeriodicBSpline curve(points);
    const double scale = extent_of(points) + points.front().norm();
    const std::size_t n = curve.size();
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t next = (j + 1) % n;
      EXPECT_LE((curve.point(j, 1.0) - curve.point(next, 0.0)).norm(), 1e-13 * scale);
      EXPECT_LE((curve.derivative(j, 1.0) - curve.derivative(next, 0.0)).norm(), 1e-13 * scale);
      EXPECT_LE((curve.second_derivative(j, 1.0) - curve.second_derivative(next, 0.0)).norm(),
                1e-12 * scale);
    }
  }
}

TEST(PeriodicBSpline, GlobalParameterWrapsBothWays) {
  const PeriodicBSpline curve({{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 1}});
  const CurveParam p = curve.locate(7.25);
  EXPECT_EQ(p.segment, 2u);
  EXPECT_DOUBLE_EQ(p.t, 0.25);
  const CurveParam q = curve.locate(-0.75);
  EXPECT_EQ(q.segment, 4u);
  EXPECT_DOUBLE_EQ(q.t, 0.25);
  const CurveParam r = curve.locate(-1e-18);  // rounds to the period: must stay in range
  EXPECT_LT(r.segment, 5u);
  EXPECT_LT(r.t, 1.0);
  EXPECT_EQ(curve.point_at(2.25), curve.point(2, 0.25));
}

TEST(CubicSegment, BezierFormDescribesTheSameCubic) {
  Rng rng(4);
  for (int c = 0; c < kCases; ++c) {
    const auto points = random_control_polygon(rng, 4);
    const CubicSegment s(points[0], points[1], points[2], points[3]);
    const auto& b = s.bezier();
    const double scale = extent_of(points) + points.front().norm();
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
      const double u = 1.0 - t;
      const Vec2 bernstein =
          u * u * u * b[0] + 3 * u * u * t * b[1] + 3 * u * t * t * b[2] + t * t * t * b[3];
      EXPECT_LE((bernstein - s.point(t)).norm(), 1e-13 * scale);
    }
  }
}

TEST(CubicSegment, HullBoundsContainDenseSamples) {
  Rng rng(5);
  for (int c = 0; c < kCases; ++c) {
    const PeriodicBSpline curve(random_control_polygon(rng, random_segment_count(rng, c)));
    const Aabb whole = curve.hull_bounds();
    for (std::size_t j = 0; j < curve.size(); j += 1 + curve.size() / 64) {
      const Aabb box = curve.segment(j).hull_bounds();
      const double slack = 1e-14 * (box.diagonal() + box.max.norm());
      for (int k = 0; k <= 1000; ++k) {
        const Vec2 p = curve.point(j, k / 1000.0);
        ASSERT_TRUE(box.contains(p, slack)) << "segment " << j << " t " << k / 1000.0;
        ASSERT_TRUE(whole.contains(p, slack));
      }
    }
  }
}

TEST(Subdivision, ReproducesTheCurveExactly) {
  Rng rng(6);
  for (int c = 0; c < kCases; ++c) {
    const std::size_t n = random_segment_count(rng, c);
    const PeriodicBSpline coarse(random_control_polygon(rng, n));
    const int levels = n <= 64 ? 3 : 1;
    const PeriodicBSpline fine = subdivide(coarse, levels);
    ASSERT_EQ(fine.size(), n << levels);
    const double scale = coarse.hull_bounds().diagonal() + coarse.control_points()[0].norm();
    const double pieces = static_cast<double>(1 << levels);
    for (int k = 0; k < 64; ++k) {
      const double u = rng.uniform(0.0, static_cast<double>(n));
      // Coarse parameter u is fine parameter u * 2^levels.
      EXPECT_LE((coarse.point_at(u) - fine.point_at(u * pieces)).norm(), 1e-12 * scale);
      EXPECT_LE((coarse.derivative_at(u) - pieces * fine.derivative_at(u * pieces)).norm(),
                1e-11 * scale);
    }
  }
}

}  // namespace
}  // namespace rugosim

namespace rugosim {
namespace {

TEST(CubicSegment, TransformedSegmentIsThePlacedCurve) {
  Rng rng(8);
  for (int c = 0; c < 200; ++c) {
    const auto points = testing::random_control_polygon(rng, 4);
    const CubicSegment s(points[0], points[1], points[2], points[3]);
    const Transform2 x(rng.uniform(-4, 4), Vec2(rng.uniform(-9, 9), rng.uniform(-9, 9)));
    const CubicSegment placed = s.transformed(x);
    const double scale = testing::extent_of(points) + points[0].norm() + 10.0;
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      EXPECT_LE((placed.point(t) - x.apply(s.point(t))).norm(), 1e-13 * scale);
      EXPECT_LE((placed.derivative(t) - x.rotate(s.derivative(t))).norm(), 1e-13 * scale);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_LE((placed.bezier()[k] - x.apply(s.bezier()[k])).norm(), 1e-13 * scale);
    }
  }
}

}  // namespace
}  // namespace rugosim
