#include "engine/geometry/mass_properties.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/shapes.h"
#include "engine/geometry/subdivision.h"
#include "support/random_curves.h"

namespace rugosim {
namespace {

using testing::random_control_polygon;
using testing::random_segment_count;

constexpr int kCases = 300;

// The shape generator's circle (knot points on radius R), moved to `centre`.
std::vector<Vec2> spline_circle(std::size_t n, double radius, const Vec2& centre) {
  std::vector<Vec2> points = circle_control_points(radius, n);
  for (Vec2& p : points)
    p += centre;
  return points;
}

// The same quantities by a route that shares nothing with the implementation: the textbook
// one-sided Green forms ∫∫x dA = ∮ x²/2 dy, ∫∫y dA = −∮ y²/2 dx, ∫∫x² dA = ∮ x³/3 dy,
// ∫∫y² dA = −∮ y³/3 dx, A = ∮ x dy, integrated through point() and derivative() by composite
// 5-point Gauss-Legendre (4 sub-intervals per segment; the rule's error on the degree-11
// integrands is then below 1e-11 relative).
MassProperties integrate_numerically(const PeriodicBSpline& curve) {
  constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0.0,
                                         0.5384693101056831, 0.9061798459386640};
  constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665,
                                           0.5688888888888889, 0.4786286704993665,
                                           0.2369268850561891};
  constexpr int kSub = 4;
  const Vec2 ref = curve.hull_bounds().center();
  double area = 0.0, sx = 0.0, sy = 0.0, ixx = 0.0, iyy = 0.0;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (int s = 0; s < kSub; ++s) {
      for (std::size_t g = 0; g < kNodes.size(); ++g) {
        const double t = (s + 0.5 * (1.0 + kNodes[g])) / kSub;
        const double w = kWeights[g] / (2.0 * kSub);
        const Vec2 p = curve.point(j, t) - ref;
        const Vec2 d = curve.derivative(j, t);
        area += w * p.x() * d.y();
        sx += w * p.x() * p.x() * d.y() / 2.0;
        sy -= w * p.y() * p.y() * d.x() / 2.0;
        ixx += w * p.x() * p.x() * p.x() * d.y() / 3.0;
        iyy -= w * p.y() * p.y() * p.y() * d.x() / 3.0;
      }
    }
  }
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const Vec2 c(sx / area, sy / area);
  MassProperties m;
  m.area = sign * area;
  m.centroid = ref + c;
  m.polar_moment = sign * (ixx + iyy - area * c.squaredNorm());
  return m;
}

std::string scientific(double x) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(3) << x;
  return out.str();
}

double relative(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

TEST(MassProperties, MatchesDenseGreenQuadrature) {
  Rng rng(101);
  double worst_area = 0.0, worst_centroid = 0.0, worst_polar = 0.0;
  for (int c = 0; c < kCases; ++c) {
    const PeriodicBSpline curve(random_control_polygon(rng, random_segment_count(rng, c)));
    const MassProperties exact = compute_mass_properties(curve);
    const MassProperties dense = integrate_numerically(curve);
    const double size = std::sqrt(dense.area);
    worst_area = std::max(worst_area, relative(exact.area, dense.area));
    worst_centroid = std::max(worst_centroid, (exact.centroid - dense.centroid).norm() / size);
    worst_polar = std::max(worst_polar, relative(exact.polar_moment, dense.polar_moment));
    EXPECT_GT(exact.area, 0.0);
    EXPECT_NEAR(signed_area(curve), exact.area, 1e-12 * exact.area);
  }
  EXPECT_LE(worst_area, 1e-9);
  EXPECT_LE(worst_centroid, 1e-9);
  EXPECT_LE(worst_polar, 1e-9);
  RecordProperty("worst_area", scientific(worst_area));
  RecordProperty("worst_centroid", scientific(worst_centroid));
  RecordProperty("worst_polar", scientific(worst_polar));
}

TEST(MassProperties, EitherOrientationGivesTheSameProperties) {
  Rng rng(102);
  for (int c = 0; c < kCases; ++c) {
    auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const PeriodicBSpline forward(points);
    std::reverse(points.begin(), points.end());
    const PeriodicBSpline backward(points);
    const MassProperties a = compute_mass_properties(forward);
    const MassProperties b = compute_mass_properties(backward);
    EXPECT_LT(signed_area(backward), 0.0);
    EXPECT_NEAR(signed_area(backward), -signed_area(forward), 1e-12 * a.area);
    EXPECT_NEAR(b.area, a.area, 1e-12 * a.area);
    EXPECT_LE((b.centroid - a.centroid).norm(), 1e-12 * std::sqrt(a.area));
    EXPECT_NEAR(b.polar_moment, a.polar_moment, 1e-12 * a.polar_moment);
  }
}

TEST(MassProperties, TranslationMovesOnlyTheCentroid) {
  Rng rng(103);
  for (int c = 0; c < kCases; ++c) {
    auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const MassProperties before = compute_mass_properties(PeriodicBSpline(points));
    const double size = std::sqrt(before.area);
    // Up to 100 body sizes away: the reference point keeps the integrands well scaled.
    const Vec2 offset = size * 100.0 * Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1));
    for (Vec2& p : points)
      p += offset;
    const MassProperties after = compute_mass_properties(PeriodicBSpline(points));
    EXPECT_NEAR(after.area, before.area, 1e-11 * before.area);
    EXPECT_LE((after.centroid - (before.centroid + offset)).norm(), 1e-11 * size);
    EXPECT_NEAR(after.polar_moment, before.polar_moment, 1e-11 * before.polar_moment);
  }
}

TEST(MassProperties, RotationKeepsAreaAndPolarMoment) {
  Rng rng(104);
  for (int c = 0; c < kCases; ++c) {
    auto points = random_control_polygon(rng, random_segment_count(rng, c));
    const MassProperties before = compute_mass_properties(PeriodicBSpline(points));
    const Mat2 rotation = Eigen::Rotation2Dd(rng.uniform(0.0, 2.0 * std::numbers::pi)).matrix();
    for (Vec2& p : points)
      p = rotation * p;
    const MassProperties after = compute_mass_properties(PeriodicBSpline(points));
    const double size = std::sqrt(before.area);
    EXPECT_NEAR(after.area, before.area, 1e-12 * before.area);
    EXPECT_LE((after.centroid - rotation * before.centroid).norm(),
              1e-12 * (size + before.centroid.norm()));
    EXPECT_NEAR(after.polar_moment, before.polar_moment, 1e-11 * before.polar_moment);
  }
}

TEST(MassProperties, SplineCircleApproachesTheDisk) {
  // With its knot points on the circle, the curve dips inside it between the knots by O(h⁴),
  // h = 2π/n: the area falls short by about 4.33/n⁴ relative (measured: 6.9e-5, 2.6e-7,
  // 1.0e-9, 3.9e-12 for n = 16, 64, 256, 1024) and J by twice that.
  const double radius = 0.7;
  const Vec2 centre(3.0, -2.0);
  const double disk_area = std::numbers::pi * radius * radius;
  const double disk_polar = 0.5 * std::numbers::pi * std::pow(radius, 4);
  double previous_area_error = 1.0, previous_polar_error = 1.0;
  for (std::size_t n : {16u, 64u, 256u, 1024u}) {
    const MassProperties m =
        compute_mass_properties(PeriodicBSpline(spline_circle(n, radius, centre)));
    const double area_error = relative(m.area, disk_area);
    const double polar_error = relative(m.polar_moment, disk_polar);
    const double n4 = std::pow(static_cast<double>(n), 4);
    EXPECT_LT(m.area, disk_area);
    EXPECT_LE(area_error, 5.0 / n4) << n;
    EXPECT_LE(polar_error, 10.0 / n4) << n;
    // Fourth order: a 4-fold finer curve is about 256 times closer.
    EXPECT_LT(area_error, previous_area_error / 200.0) << n;
    EXPECT_LT(polar_error, previous_polar_error / 200.0) << n;
    // Inertia ½ m R² per unit density is the same statement as J = ½πR⁴.
    const double density = 2.0;
    EXPECT_NEAR(m.inertia(density), 0.5 * m.mass(density) * radius * radius,
                2.0 * (area_error + polar_error) * m.inertia(density));
    EXPECT_LE((m.centroid - centre).norm(), 1e-13 * radius);
    previous_area_error = area_error;
    previous_polar_error = polar_error;
    RecordProperty("area_error_n" + std::to_string(n), scientific(area_error));
    RecordProperty("polar_error_n" + std::to_string(n), scientific(polar_error));
  }
}

TEST(MassProperties, TripleCornerPointsGiveTheExactRectangle) {
  // Four collinear control points give a straight segment, so with each corner repeated
  // three times the curve is exactly the rectangle.
  Rng rng(105);
  for (int c = 0; c < 50; ++c) {
    const double w = std::pow(10.0, rng.uniform(-2.0, 2.0));
    const double h = std::pow(10.0, rng.uniform(-2.0, 2.0));
    const Vec2 o(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0));
    std::vector<Vec2> points;
    for (const Vec2& corner : {o, Vec2(o + Vec2(w, 0)), Vec2(o + Vec2(w, h)), Vec2(o + Vec2(0, h))})
      points.insert(points.end(), 3, corner);
    const MassProperties m = compute_mass_properties(PeriodicBSpline(points));
    EXPECT_NEAR(m.area, w * h, 1e-12 * w * h);
    EXPECT_LE((m.centroid - (o + Vec2(w / 2, h / 2))).norm(), 1e-12 * (w + h + o.norm()));
    const double polar = w * h * (w * w + h * h) / 12.0;
    EXPECT_NEAR(m.polar_moment, polar, 1e-12 * polar);
  }
}

// Shoelace area of the closed polygon through f(i/k) on every segment, and the bound on how far
// it may be from the curve's area: on a piece of parameter length h the arc strays at most
// δ = max|f''| h²/8 from its chord (f − chord = e, |e| ≤ δ), and the two areas differ by
// ∫ e × chord' + ½ ∫ e × e', at most δ·(chord + ½ ∫|e'|) ≤ 2δ·(|f'(t₀)| + max|f''| h)·h.
struct InscribedPolygon {
  double area = 0.0;   // m²
  double bound = 0.0;  // m²
};

InscribedPolygon inscribed_polygon(const PeriodicBSpline& curve, std::size_t pieces) {
  const double h = 1.0 / static_cast<double>(pieces);
  const Vec2 ref = curve.point(0, 0.0);
  InscribedPolygon result;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    const double curvature =
        std::max(curve.second_derivative(j, 0.0).norm(), curve.second_derivative(j, 1.0).norm());
    for (std::size_t i = 0; i < pieces; ++i) {
      const double t = static_cast<double>(i) * h;
      const Vec2 a = curve.point(j, t) - ref;
      const Vec2 b =
          (i + 1 < pieces ? curve.point(j, t + h) : curve.point((j + 1) % curve.size(), 0.0)) - ref;
      result.area += cross(a, b) / 2.0;
      const double speed = curve.derivative(j, t).norm() + curvature * h;
      result.bound += 2.0 * (curvature * h * h / 8.0) * speed * h;
    }
  }
  return result;
}

TEST(MassProperties, AgreesWithTheAreaOfAFineInscribedPolygon) {
  Rng rng(106);
  for (int c = 0; c < 100; ++c) {
    const PeriodicBSpline curve(random_control_polygon(rng, random_segment_count(rng, c)));
    const double area = compute_mass_properties(curve).area;
    const InscribedPolygon coarse = inscribed_polygon(curve, 32);
    const InscribedPolygon fine = inscribed_polygon(curve, 64);
    EXPECT_LE(std::abs(coarse.area - area), coarse.bound + 1e-12 * area);
    EXPECT_LE(std::abs(fine.area - area), fine.bound + 1e-12 * area);
    // Second order: halving the pieces' length quarters the difference.
    const double ratio = (coarse.area - area) / (fine.area - area);
    EXPECT_NEAR(ratio, 4.0, 0.1) << "case " << c;
  }
}

TEST(MassProperties, SubdivisionKeepsThePropertiesOfTheSameCurve) {
  Rng rng(107);
  for (int c = 0; c < 100; ++c) {
    const PeriodicBSpline coarse(random_control_polygon(rng, random_segment_count(rng, c)));
    const MassProperties a = compute_mass_properties(coarse);
    const MassProperties b = compute_mass_properties(subdivide(coarse, 2));
    EXPECT_NEAR(b.area, a.area, 1e-12 * a.area);
    EXPECT_LE((b.centroid - a.centroid).norm(), 1e-12 * std::sqrt(a.area));
    EXPECT_NEAR(b.polar_moment, a.polar_moment, 1e-11 * a.polar_moment);
  }
}

TEST(MassProperties, MassAndInertiaScaleWithDensity) {
  const MassProperties m =
      compute_mass_properties(PeriodicBSpline(spline_circle(32, 1.0, Vec2::Zero())));
  EXPECT_DOUBLE_EQ(m.mass(3.0), 3.0 * m.area);
  EXPECT_DOUBLE_EQ(m.inertia(3.0), 3.0 * m.polar_moment);
}

TEST(MassProperties, RejectsABoundaryWithoutArea) {
  // Collinear control points: the curve runs back and forth along a line.
  EXPECT_THROW(compute_mass_properties(PeriodicBSpline({{0, 0}, {1, 1}, {3, 3}, {2, 2}})),
               std::invalid_argument);
  EXPECT_EQ(signed_area(PeriodicBSpline({{0, 0}, {1, 0}, {3, 0}, {2, 0}})), 0.0);
}

}  // namespace
}  // namespace rugosim
