// Curve length (curve_length.h): exact for the straight sides of a sharp box, the circle's
// circumference for the spline circle, and a fine polyline's length for seeded random curves.
#include "engine/geometry/curve_length.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

TEST(CurveLength, SharpBoxIsItsPerimeter) {
  EXPECT_NEAR(curve_length(PeriodicBSpline(box_control_points(0.8, 0.3, 24))), 2.2, 1e-9);
}

TEST(CurveLength, SplineCircleIsNearlyTheCircumference) {
  // The spline dips inside the circle by about 0.0026·(2π/n)⁴·r between knots.
  const double r = 0.5;
  const double length = curve_length(PeriodicBSpline(circle_control_points(r, 64)));
  EXPECT_NEAR(length, 2.0 * std::numbers::pi * r, 1e-6 * r);
}

TEST(CurveLength, MatchesAFinePolylineOnRandomCurves) {
  for (std::size_t trial = 0; trial < 20; ++trial) {
    const PeriodicBSpline curve(blob_control_points(0.3, 0.6, 8 + trial, trial));
    double polyline = 0.0;
    for (std::size_t j = 0; j < curve.size(); ++j) {
      const CubicSegment& s = curve.segment(j);
      Vec2 previous = s.point(0.0);
      for (int i = 1; i <= 4000; ++i) {
        const Vec2 p = s.point(i / 4000.0);
        polyline += (p - previous).norm();
        previous = p;
      }
    }
    EXPECT_NEAR(curve_length(curve), polyline, 1e-6 * polyline) << "trial " << trial;
  }
}

}  // namespace
}  // namespace rugosim
