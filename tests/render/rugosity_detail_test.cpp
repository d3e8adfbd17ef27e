// Rugosity detail (rugosity_detail.h): σ = 0 draws the curve itself; the drawn displacement has
// the documented RMS σ/√2 × roughness_scale; it is a property of the body (the same spectrum
// and shape at 720p and 4K, alike on long and short segments); same seed, same outline.
#include "render/draw/rugosity_detail.h"

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

PeriodicBSpline circle(double radius, std::size_t n) {
  return PeriodicBSpline(circle_control_points(radius, n));
}

double rms(const std::vector<double>& values) {
  double sum2 = 0.0;
  for (const double v : values)
    sum2 += v * v;
  return std::sqrt(sum2 / static_cast<double>(values.size()));
}

TEST(RugosityDetail, WithoutRoughnessThePointsLieOnTheCurveAtEqualSteps) {
  const PeriodicBSpline curve = circle(1.0, 64);
  const DetailOutline out =
      make_detail_outline(curve, std::vector<double>(64, 0.0), 1, {.pixel_size = 1e-3});
  ASSERT_EQ(out.points.size(), out.param.size());
  EXPECT_EQ(out.octaves, 0);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Vec2 expected = curve.point_at(out.param[i]);
    EXPECT_NEAR((out.points[i] - expected).norm(), 0.0, 1e-12) << i;
    const Vec2& next = out.points[(i + 1) % out.points.size()];
    // Equal steps of arc length: chords of a unit circle's B-spline, within 0.1%.
    const double step = out.length / static_cast<double>(out.points.size());
    EXPECT_NEAR((next - out.points[i]).norm(), step, 1e-3 * step) << i;
  }
}

// Samples every 1.5 px, or closer where the finest octave drawn needs two a lattice cell; at
// least four a segment and at most 2^16; octaves under a pixel, or that would need more
// samples than that, are left out.
TEST(RugosityDetail, SamplesFollowThePixelsAndTheFinestOctave) {
  const PeriodicBSpline curve = circle(1.0, 32);
  for (const double sigma : {0.0, 0.01}) {
    for (const double pixel : {1.0, 0.1, 0.01, 1e-3, 1e-4, 1e-6}) {
      const DetailOutline out =
          make_detail_outline(curve, std::vector<double>(32, sigma), 3, {.pixel_size = pixel});
      const std::size_t n = out.points.size();
      const double step = out.length / static_cast<double>(n);
      EXPECT_GE(n, 4u * 32u) << pixel;  // a smooth shape when zoomed out
      EXPECT_LE(n, std::size_t{1} << 16) << pixel;
      if (n == 4u * 32u || n == (std::size_t{1} << 16)) continue;
      EXPECT_LE(step, 1.5 * pixel) << pixel;
      double finest = 0.0;
      if (out.octaves > 0) {
        finest = out.length /
                 std::round(out.length / std::ldexp(out.correlation_length, 1 - out.octaves));
        EXPECT_LE(step, finest / 2.0) << pixel;
        EXPECT_GE(finest, pixel) << pixel;
      }
      if (sigma == 0.0) {
        EXPECT_GT(step, 1.5 * pixel * 0.99) << pixel;
      }
      if (sigma > 0.0 && out.octaves < 12) {
        // The next octave is under a pixel, or its samples would pass max_points.
        const double next = finest / 2.0;
        EXPECT_TRUE(next < pixel * 1.01 || out.length / (next / 2.0) > 65536 * 0.99) << pixel;
      }
    }
  }
}

// The documented statistic: d has RMS σ/√2 × roughness_scale (the B-spline through control
// points displaced by N(0, σ²), the paper's model, moves the curve by σ/√2), within 10%.
TEST(RugosityDetail, DisplacementRmsIsSigmaOverRootTwoTimesTheScale) {
  const double sigma = 0.002;
  const PeriodicBSpline curve = circle(5.0, 256);
  for (const double scale : {1.0, 3.0, 10.0}) {
    for (const std::uint64_t seed : {1u, 2u}) {
      const DetailOutline out = make_detail_outline(
          curve, std::vector<double>(256, sigma), seed,
          {.pixel_size = 4e-4, .max_points = std::size_t{1} << 18, .roughness_scale = scale});
      EXPECT_GE(out.octaves, 4) << scale;
      EXPECT_NEAR(rms(out.displacement) / (scale * sigma / std::sqrt(2.0)), 1.0, 0.1)
          << "scale " << scale << " seed " << seed;
      // The displacement recorded is the one drawn: along the normal, from the curve.
      for (std::size_t i = 0; i < out.points.size(); i += 97) {
        const double off = (out.points[i] - curve.point_at(out.param[i])).norm();
        EXPECT_NEAR(off, std::abs(out.displacement[i]), 1e-9 + 1e-3 * off) << i;
      }
    }
  }
}

// Power of d in the frequency band [k0, k1) cycles per boundary, from its samples (equal
// steps over one period): the same for any sample count when the signal is resolved.
double band_power(const std::vector<double>& d, int k0, int k1) {
  const auto n = static_cast<double>(d.size());
  double power = 0.0;
  for (int k = k0; k < k1; ++k) {
    std::complex<double> sum = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i)
      sum += d[i] * std::polar(1.0, -2.0 * M_PI * k * static_cast<double>(i) / n);
    power += std::norm(sum / n);
  }
  return power;
}

// Correlation of two displacements at the first one's arc lengths (the second linear between
// its samples): 1 for the same shape.
double shape_correlation(const DetailOutline& a, const DetailOutline& b) {
  double ab = 0.0, aa = 0.0, bb = 0.0;
  const std::size_t n = b.points.size();
  const double step = b.length / static_cast<double>(n);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const double x = a.arc_length[i] / step;
    const auto j = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(j);
    const double at_b = (1.0 - f) * b.displacement[j % n] + f * b.displacement[(j + 1) % n];
    ab += a.displacement[i] * at_b;
    aa += a.displacement[i] * a.displacement[i];
    bb += at_b * at_b;
  }
  return ab / std::sqrt(aa * bb);
}

// A 20 cm rock in a 720p and a 4K view of a 3 m tall scene, σ from 3 to 12 mm, eight seeds
// each. The 4K outline draws the 720p one's octaves and one or two finer ones (those under a
// 720p pixel, which it leaves out): summed over the seeds, the band powers agree within 15% in
// every octave band of wavelengths of four lattice cells of the finest octave 720p draws and
// more (measured: within 7%, but for the single frequency of one turn at σ = 3 mm, 13%), and
// each seed's two displacements at the same arc lengths correlate above 0.9 (the octaves 720p
// leaves out hold at most 2^(−3.2) = 11% of the variance).
TEST(RugosityDetail, SameSpectrumAndShapeAt720pAnd4K) {
  const PeriodicBSpline rock = circle(0.1, 24);
  const double pixel = 3.0 / 720.0;
  for (const double s : {0.012, 0.006, 0.003}) {
    const std::vector<double> sigma(24, s);
    std::vector<double> low_power, high_power;
    int top = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const DetailOutline low = make_detail_outline(rock, sigma, seed, {.pixel_size = pixel});
      const DetailOutline high =
          make_detail_outline(rock, sigma, seed, {.pixel_size = 3.0 / 2160.0});
      ASSERT_GE(low.octaves, 2);
      ASSERT_GT(high.octaves, low.octaves);
      ASSERT_LT(low.points.size(), high.points.size());
      ASSERT_EQ(low.correlation_length, high.correlation_length);
      // Cycles of four lattice cells of the finest octave 720p draws.
      top = static_cast<int>(low.length /
                             (4.0 * std::ldexp(low.correlation_length, 1 - low.octaves)));
      std::size_t band = 0;
      for (int k0 = 1; 2 * k0 <= top; k0 *= 2, ++band) {
        if (seed == 1) {
          low_power.push_back(0.0);
          high_power.push_back(0.0);
        }
        low_power[band] += band_power(low.displacement, k0, 2 * k0);
        high_power[band] += band_power(high.displacement, k0, 2 * k0);
      }
      EXPECT_GT(shape_correlation(low, high), 0.9) << s << " " << seed;
    }
    ASSERT_GE(low_power.size(), 3u);
    for (std::size_t band = 0; band < low_power.size(); ++band) {
      EXPECT_NEAR(low_power[band] / high_power[band], 1.0, 0.15)
          << "σ " << s << ", cycles from " << (1 << band);
    }
  }
}

// A curve whose first half has segments four times longer than the second's, equal σ
// everywhere: the detail is as wavy per metre in both halves (zero crossings per metre within
// 25%) and as strong (RMS within 20%).
TEST(RugosityDetail, SegmentsOfEqualSigmaLookAlikeWhateverTheirLength) {
  std::vector<Vec2> control;
  for (int i = 0; i < 16; ++i) {  // 16 long steps over half the circle, 64 short ones after
    const double a = M_PI * i / 16.0;
    control.emplace_back(2.0 * std::cos(a), 2.0 * std::sin(a));
  }
  for (int i = 0; i < 64; ++i) {
    const double a = M_PI + M_PI * i / 64.0;
    control.emplace_back(2.0 * std::cos(a), 2.0 * std::sin(a));
  }
  const PeriodicBSpline curve(control);
  const DetailOutline out =
      make_detail_outline(curve, std::vector<double>(80, 0.004), 3, {.pixel_size = 1e-3});
  double crossings[2] = {0, 0}, length[2] = {0, 0}, sum2[2] = {0, 0}, count[2] = {0, 0};
  const double step = out.length / static_cast<double>(out.points.size());
  for (std::size_t i = 0; i + 1 < out.points.size(); ++i) {
    const int half = out.param[i] < 16.0 ? 0 : 1;
    length[half] += step;
    crossings[half] += (out.displacement[i] > 0.0) != (out.displacement[i + 1] > 0.0) ? 1 : 0;
    sum2[half] += out.displacement[i] * out.displacement[i];
    count[half] += 1;
  }
  EXPECT_NEAR((crossings[0] / length[0]) / (crossings[1] / length[1]), 1.0, 0.25);
  EXPECT_NEAR(std::sqrt(sum2[0] / count[0]) / std::sqrt(sum2[1] / count[1]), 1.0, 0.2);
}

TEST(RugosityDetail, SmoothSegmentsStaySmoothBesideRoughOnes) {
  const PeriodicBSpline curve = circle(1.0, 16);
  std::vector<double> sigma(16, 0.0);
  for (std::size_t j = 0; j < 8; ++j)
    sigma[j] = 0.01;
  const DetailOutline out = make_detail_outline(curve, sigma, 9, {.pixel_size = 1e-3});
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
  const PeriodicBSpline curve = circle(1.0, 24);
  const std::vector<double> sigma(24, 0.01);
  const DetailSettings s{.pixel_size = 2e-3};
  const DetailOutline a = make_detail_outline(curve, sigma, 11, s);
  const DetailOutline b = make_detail_outline(curve, sigma, 11, s);
  const DetailOutline c = make_detail_outline(curve, sigma, 12, s);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(RugosityDetail, ScaleZeroDrawsTheSmoothCurve) {
  const PeriodicBSpline curve = circle(1.0, 24);
  const DetailOutline out = make_detail_outline(curve, std::vector<double>(24, 0.01), 11,
                                                {.pixel_size = 2e-3, .roughness_scale = 0.0});
  EXPECT_EQ(rms(out.displacement), 0.0);
}

// A sharp corner (tripled control points: c'(u) = 0 there) and the extremes of size: every
// point finite, and detail far below a pixel not drawn at all.
TEST(RugosityDetail, SharpCornersAndExtremeSizesStayFinite) {
  const PeriodicBSpline triangle(
      std::vector<Vec2>{{0, 0}, {0, 0}, {0, 0}, {1, 0}, {1, 0}, {1, 0}, {0, 1}, {0, 1}, {0, 1}});
  for (const double size : {1e-6, 1.0, 1e4}) {
    std::vector<Vec2> scaled;
    for (const Vec2& c : triangle.control_points())
      scaled.push_back(c * size);
    const DetailOutline out =
        make_detail_outline(PeriodicBSpline(scaled), std::vector<double>(9, 0.02 * size), 5,
                            {.pixel_size = size / 500});
    EXPECT_GT(out.octaves, 0) << size;
    for (const Vec2& p : out.points)
      ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y())) << size;
  }
  const DetailOutline tiny =
      make_detail_outline(circle(1.0, 16), std::vector<double>(16, 1e-7), 5, {.pixel_size = 1e-3});
  EXPECT_EQ(tiny.octaves, 0);
  EXPECT_EQ(rms(tiny.displacement), 0.0);
}

TEST(RugosityDetail, OutlineIsCounterClockwiseWhateverTheCurve) {
  std::vector<Vec2> clockwise = circle_control_points(1.0, 20);
  std::reverse(clockwise.begin(), clockwise.end());
  const DetailOutline out = make_detail_outline(
      PeriodicBSpline(clockwise), std::vector<double>(20, 0.001), 1, {.pixel_size = 0.001});
  double twice_area = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const Vec2& a = out.points[i];
    const Vec2& b = out.points[(i + 1) % out.points.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_GT(twice_area, 0.0);
}

TEST(RugosityDetail, RejectsBadInput) {
  const PeriodicBSpline curve = circle(1.0, 8);
  const std::vector<double> flat(8, 0.0);
  EXPECT_THROW(make_detail_outline(curve, std::vector<double>(7, 0.0), 1, {.pixel_size = 0.01}),
               std::invalid_argument);
  EXPECT_THROW(make_detail_outline(curve, flat, 1, {.pixel_size = 0.0}), std::invalid_argument);
  EXPECT_THROW(make_detail_outline(curve, flat, 1, {.pixel_size = 0.01, .roughness_scale = -1}),
               std::invalid_argument);
  EXPECT_THROW(make_detail_outline(curve, flat, 1, {.pixel_size = 0.01, .correlation_length = NAN}),
               std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
