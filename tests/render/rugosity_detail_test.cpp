// Rugosity detail (rugosity_detail.h): σ = 0 draws the curve itself; the noise has the
// statistics the paper gives it; the level follows the pixel size; same seed, same outline.
#include "render/draw/rugosity_detail.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

PeriodicBSpline unit_circle(std::size_t n) {
  return PeriodicBSpline(circle_control_points(1.0, n));
}

TEST(RugosityDetail, WithoutRoughnessThePointsLieOnTheCurve) {
  const PeriodicBSpline curve = unit_circle(64);
  const std::vector<double> sigma(64, 0.0);
  const DetailOutline out =
      make_detail_outline(curve, sigma, 1, DetailSettings{.pixel_size = 1e-3});
  ASSERT_GT(out.level, 0);
  ASSERT_EQ(out.points.size(), out.param.size());
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Vec2 expected = curve.point_at(out.param[i]);
    EXPECT_NEAR((out.points[i] - expected).norm(), 0.0, 1e-12) << i;
  }
}

TEST(RugosityDetail, LevelKeepsPointsAtLeastTheSpacingApart) {
  const PeriodicBSpline curve = unit_circle(32);
  const std::vector<double> sigma(32, 0.01);
  for (const double pixel : {1.0, 0.1, 0.01, 1e-3, 1e-4}) {
    const DetailOutline out =
        make_detail_outline(curve, sigma, 3, DetailSettings{.pixel_size = pixel});
    const double spacing = 2.0 * M_PI / static_cast<double>(out.points.size());
    if (out.level > 0) {
      EXPECT_GE(spacing, 1.5 * pixel * 0.9) << pixel;  // ±10%: chords against the arc
    }
    if (out.level < 8) {
      EXPECT_LT(spacing, 2.0 * 1.5 * pixel * 1.1) << pixel;  // one level finer would be too fine
    }
    EXPECT_LE(out.points.size(), std::size_t{1} << 16);
  }
}

// The drawn point k is (c[k−1] + 4c[k] + c[k+1]) / 6 of control points displaced by
// independent N(0, σ²) along (nearly) the same normal, so it moves by N(0, σ²·18/36): its
// standard deviation is σ/√2.
TEST(RugosityDetail, DisplacementHasTheStatisticsOfTheModel) {
  const double sigma_value = 0.002;
  const PeriodicBSpline curve = unit_circle(128);
  const std::vector<double> sigma(128, sigma_value);
  const DetailOutline smooth = make_detail_outline(curve, std::vector<double>(128, 0.0), 5,
                                                   DetailSettings{.pixel_size = 2e-4});
  const DetailOutline rough =
      make_detail_outline(curve, sigma, 5, DetailSettings{.pixel_size = 2e-4});
  ASSERT_EQ(smooth.points.size(), rough.points.size());
  ASSERT_GE(rough.points.size(), 16384u);
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < rough.points.size(); ++i) {
    const double d = rough.points[i].norm() - smooth.points[i].norm();  // radial
    sum += d;
    sum2 += d * d;
  }
  const auto n = static_cast<double>(rough.points.size());
  const double mean = sum / n;
  const double deviation = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 5.0 * deviation / std::sqrt(n));  // five standard errors
  EXPECT_NEAR(deviation / (sigma_value / std::sqrt(2.0)), 1.0, 0.05);
}

TEST(RugosityDetail, SmoothSegmentsStaySmoothBesideRoughOnes) {
  const PeriodicBSpline curve = unit_circle(16);
  std::vector<double> sigma(16, 0.0);
  for (std::size_t j = 0; j < 8; ++j)
    sigma[j] = 0.01;
  const DetailOutline out =
      make_detail_outline(curve, sigma, 9, DetailSettings{.pixel_size = 1e-3});
  double rough_part = 0.0, smooth_part = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const double off = std::abs((out.points[i] - curve.point_at(out.param[i])).norm());
    // Segments 10..14 are two segments away from any rough one.
    if (out.param[i] >= 10.0 && out.param[i] < 14.0) smooth_part = std::max(smooth_part, off);
    if (out.param[i] >= 2.0 && out.param[i] < 6.0) rough_part = std::max(rough_part, off);
  }
  EXPECT_LT(smooth_part, 1e-12);
  EXPECT_GT(rough_part, 0.01);
}

TEST(RugosityDetail, SameSeedSameOutlineOtherSeedOther) {
  const PeriodicBSpline curve = unit_circle(24);
  const std::vector<double> sigma(24, 0.01);
  const DetailSettings s{.pixel_size = 2e-3};
  const DetailOutline a = make_detail_outline(curve, sigma, 11, s);
  const DetailOutline b = make_detail_outline(curve, sigma, 11, s);
  const DetailOutline c = make_detail_outline(curve, sigma, 12, s);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(RugosityDetail, OutlineIsCounterClockwiseWhateverTheCurve) {
  std::vector<Vec2> clockwise = circle_control_points(1.0, 20);
  std::reverse(clockwise.begin(), clockwise.end());
  const DetailOutline out =
      make_detail_outline(PeriodicBSpline(clockwise), std::vector<double>(20, 0.0), 1,
                          DetailSettings{.pixel_size = 0.01});
  double twice_area = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Vec2& a = out.points[i];
    const Vec2& b = out.points[(i + 1) % out.points.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_GT(twice_area, 0.0);
}

TEST(RugosityDetail, RejectsBadInput) {
  const PeriodicBSpline curve = unit_circle(8);
  EXPECT_THROW(make_detail_outline(curve, std::vector<double>(7, 0.0), 1, {.pixel_size = 0.01}),
               std::invalid_argument);
  EXPECT_THROW(make_detail_outline(curve, std::vector<double>(8, 0.0), 1, {.pixel_size = 0.0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
