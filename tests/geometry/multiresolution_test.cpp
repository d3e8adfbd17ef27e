#include "engine/geometry/multiresolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/subdivision.h"
#include "support/random_curves.h"

namespace rugosim {
namespace {

using testing::extent_of;
using testing::random_control_polygon;
using testing::random_segment_count;

constexpr int kCases = 300;

// Even control counts from 8 to 1024 of the form odd * 2^e, so that cases cover one level
// (12 = 3 * 4) up to eight (1024), and coarsest curves of 4, 5, 6, 7, ... points.
std::size_t random_wavelet_count(Rng& rng, int case_index) {
  if (case_index == 0) return 8;
  if (case_index == 1) return 1024;
  for (;;) {
    const auto e = 1 + static_cast<int>(rng.uniform() * 10.0);  // 1..10
    const std::size_t odd_limit = std::size_t{1024} >> e;       // odd * 2^e <= 1024
    const std::size_t odd =
        2 * static_cast<std::size_t>(rng.uniform() * static_cast<double>((odd_limit + 1) / 2)) + 1;
    const std::size_t n = odd << e;
    if (n >= 8 && n <= 1024) return n;
  }
}

double max_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, (a[i] - b[i]).norm());
  return worst;
}

double scale_of(const std::vector<Vec2>& points) {
  return extent_of(points) + points.front().norm();
}

// Largest distance between the two curves at random parameters (same parametrisation).
double max_curve_distance(Rng& rng, const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  const PeriodicBSpline curve_a(a), curve_b(b);
  double worst = 0.0;
  for (int k = 0; k < 16; ++k) {
    const double u = rng.uniform(0.0, static_cast<double>(a.size()));
    worst = std::max(worst, (curve_a.point_at(u) - curve_b.point_at(u)).norm());
  }
  return worst;
}

// n control points on the ellipse with semi-axes 2 and 1.
std::vector<Vec2> ellipse_points(std::size_t n) {
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    points[i] = Vec2(2.0 * std::cos(angle), std::sin(angle));
  }
  return points;
}

TEST(MaxWaveletLevels, CountsHalvingsThatKeepEvenAndAtLeastFour) {
  EXPECT_EQ(max_wavelet_levels(0), 0);
  EXPECT_EQ(max_wavelet_levels(4), 0);
  EXPECT_EQ(max_wavelet_levels(6), 0);
  EXPECT_EQ(max_wavelet_levels(7), 0);
  EXPECT_EQ(max_wavelet_levels(8), 1);
  EXPECT_EQ(max_wavelet_levels(10), 1);
  EXPECT_EQ(max_wavelet_levels(12), 1);
  EXPECT_EQ(max_wavelet_levels(16), 2);
  EXPECT_EQ(max_wavelet_levels(20), 2);
  EXPECT_EQ(max_wavelet_levels(24), 2);
  EXPECT_EQ(max_wavelet_levels(40), 3);
  EXPECT_EQ(max_wavelet_levels(1024), 8);
}

TEST(MaxWaveletLevels, AgreesWithWhatDecomposeAccepts) {
  for (std::size_t n = 4; n <= 1030; ++n) {
    std::vector<Vec2> points(n, Vec2::Zero());
    int levels = 0;
    for (;;) {
      try {
        points = decompose(points).coarse;
      } catch (const std::invalid_argument&) {
        break;
      }
      ++levels;
    }
    ASSERT_EQ(levels, max_wavelet_levels(n)) << "n = " << n;
  }
}

TEST(Wavelet, RejectsCountsWithoutALevel) {
  for (std::size_t n : {0u, 3u, 4u, 6u, 7u, 9u, 15u}) {
    const std::vector<Vec2> points(n, Vec2::Zero());
    EXPECT_THROW(decompose(points), std::invalid_argument) << "n = " << n;
  }
  const std::vector<Vec2> four(4, Vec2::Zero()), three(3, Vec2::Zero());
  EXPECT_THROW(reconstruct(four, three), std::invalid_argument);
  EXPECT_THROW(reconstruct(three, three), std::invalid_argument);
  EXPECT_EQ(reconstruct(four, four).size(), 8u);
}

TEST(Wavelet, DecomposeThenReconstructIsExact) {
  Rng rng(11);
  double worst_points = 0.0, worst_curve = 0.0;
  for (int c = 0; c < kCases; ++c) {
    const std::size_t n = random_wavelet_count(rng, c);
    const auto points = random_control_polygon(rng, n);
    const WaveletLevel level = decompose(points);
    ASSERT_EQ(level.coarse.size(), n / 2);
    ASSERT_EQ(level.details.size(), n / 2);
    const auto rebuilt = reconstruct(level.coarse, level.details);
    ASSERT_EQ(rebuilt.size(), n);
    const double scale = scale_of(points);
    worst_points = std::max(worst_points, max_distance(points, rebuilt) / scale);
    worst_curve = std::max(worst_curve, max_curve_distance(rng, points, rebuilt) / scale);
  }
  // Measured: 1.4e-16 (points) and 2.8e-16 (curves).
  EXPECT_LE(worst_points, 1e-12);
  EXPECT_LE(worst_curve, 1e-12);
}

TEST(Wavelet, SynthesisWithZeroDetailsIsSubdivision) {
  Rng rng(12);
  for (int c = 0; c < kCases; ++c) {
    const auto coarse = random_control_polygon(rng, random_segment_count(rng, c));
    const std::vector<Vec2> zero(coarse.size(), Vec2::Zero());
    const auto synthesised = reconstruct(coarse, zero);
    const auto subdivided = subdivide_control_points(coarse);
    ASSERT_EQ(synthesised.size(), subdivided.size());
    EXPECT_LE(max_distance(synthesised, subdivided), 1e-15 * scale_of(coarse));
  }
}

TEST(Wavelet, ReverseSubdivisionInvertsSubdivision) {
  Rng rng(13);
  for (int c = 0; c < kCases; ++c) {
    const auto coarse = random_control_polygon(rng, random_segment_count(rng, c));
    const WaveletLevel level = decompose(subdivide_control_points(coarse));
    const double scale = scale_of(coarse);
    EXPECT_LE(max_distance(level.coarse, coarse), 1e-12 * scale);
    const std::vector<Vec2> zero(coarse.size(), Vec2::Zero());
    EXPECT_LE(max_distance(level.details, zero), 1e-12 * scale);
  }
}

// Decomposing a unit impulse at each fine position reads one column of the analysis matrix.
TEST(Wavelet, AnalysisFiltersAreTheSamavatiBartelsOnes) {
  constexpr std::size_t kFine = 16;
  // Low-pass weights of f_{2i+k}, k = -3..3, in c_i; high-pass of f_{2i+1+k}, k = -2..2, in d_i.
  const std::array<double, 7> low = {23.0 / 196, -23.0 / 49, 9.0 / 28,  52.0 / 49,
                                     9.0 / 28,   -23.0 / 49, 23.0 / 196};
  const std::array<double, 5> high = {0.25, -1.0, 1.5, -1.0, 0.25};
  double low_sum = 0.0;
  for (double w : low)
    low_sum += w;
  EXPECT_NEAR(low_sum, 1.0, 1e-15);  // the coarse curve keeps constants
  for (std::size_t k = 0; k < kFine; ++k) {
    std::vector<Vec2> impulse(kFine, Vec2::Zero());
    impulse[k] = Vec2(1.0, -2.0);  // the two coordinates must not mix
    const WaveletLevel level = decompose(impulse);
    // Offset of fine index k from 2i (coarse) and from 2i+1 (details) for i = 2, away from
    // the wrap so that the periodic distance is the plain one.
    const auto lo = static_cast<long>(k) - 4;
    const auto hi = static_cast<long>(k) - 5;
    const double expected_low = std::abs(lo) <= 3 ? low[static_cast<std::size_t>(lo + 3)] : 0.0;
    const double expected_high = std::abs(hi) <= 2 ? high[static_cast<std::size_t>(hi + 2)] : 0.0;
    EXPECT_NEAR(level.coarse[2].x(), expected_low, 1e-15) << "fine index " << k;
    EXPECT_NEAR(level.coarse[2].y(), -2.0 * expected_low, 2e-15) << "fine index " << k;
    EXPECT_NEAR(level.details[2].x(), expected_high, 1e-15) << "fine index " << k;
    EXPECT_NEAR(level.details[2].y(), -2.0 * expected_high, 2e-15) << "fine index " << k;
  }
}

TEST(Multiresolution, AllLevelsReconstructExactly) {
  Rng rng(14);
  double worst_points = 0.0, worst_curve = 0.0;
  for (int c = 0; c < kCases; ++c) {
    const std::size_t n = random_wavelet_count(rng, c);
    const auto points = random_control_polygon(rng, n);
    const Multiresolution mr(points);
    ASSERT_EQ(mr.level_count(), max_wavelet_levels(n));
    ASSERT_GE(mr.level_count(), 1);
    for (int k = 0; k <= mr.level_count(); ++k) {
      ASSERT_EQ(mr.control_points(k).size(), n >> k);
      if (k < mr.level_count()) {
        ASSERT_EQ(mr.details(k).size(), n >> (k + 1));
      }
    }
    EXPECT_EQ(mr.control_points(0), points);
    const double scale = scale_of(points);
    for (int from = 0; from <= mr.level_count(); ++from) {
      const auto rebuilt = mr.reconstruct_finest(from);
      ASSERT_EQ(rebuilt.size(), n);
      worst_points = std::max(worst_points, max_distance(points, rebuilt) / scale);
      worst_curve = std::max(worst_curve, max_curve_distance(rng, points, rebuilt) / scale);
    }
  }
  // Measured: 3.5e-16 (points) and 3.2e-16 (curves), up to eight levels.
  EXPECT_LE(worst_points, 1e-12);
  EXPECT_LE(worst_curve, 1e-12);
}

TEST(Multiresolution, SubdividedCurveDecomposesIntoItsOrigin) {
  Rng rng(15);
  for (int c = 0; c < 50; ++c) {
    const std::size_t n = 5 + static_cast<std::size_t>(rng.uniform() * 60.0);  // 5..64
    const auto origin = random_control_polygon(rng, n);
    auto fine = origin;
    for (int k = 0; k < 3; ++k)
      fine = subdivide_control_points(fine);
    const Multiresolution mr(fine, 3);
    ASSERT_EQ(mr.level_count(), 3);
    const double scale = scale_of(origin);
    EXPECT_LE(max_distance(mr.control_points(3), origin), 1e-12 * scale);
    for (int k = 0; k < 3; ++k) {
      const std::vector<Vec2> zero(mr.details(k).size(), Vec2::Zero());
      EXPECT_LE(max_distance(mr.details(k), zero), 1e-12 * scale);
    }
  }
}

TEST(Multiresolution, CapsLevelsAndRejectsBadInput) {
  const auto points = ellipse_points(64);  // up to 4 levels: 32, 16, 8, 4
  EXPECT_EQ(Multiresolution(points).level_count(), 4);
  EXPECT_EQ(Multiresolution(points, 0).level_count(), 0);
  EXPECT_EQ(Multiresolution(points, 2).level_count(), 2);
  EXPECT_EQ(Multiresolution(points, 9).level_count(), 4);
  EXPECT_EQ(Multiresolution(ellipse_points(6)).level_count(), 0);
  EXPECT_THROW(Multiresolution(points, -2), std::invalid_argument);
  EXPECT_THROW(Multiresolution(ellipse_points(3)), std::invalid_argument);
  auto bad = points;
  bad[7].y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Multiresolution(std::move(bad)), std::invalid_argument);

  const Multiresolution mr(points, 2);
  EXPECT_EQ(mr.reconstruct_finest(0), points);
  EXPECT_NO_THROW(mr.control_points(2));
  EXPECT_THROW(mr.control_points(3), std::out_of_range);
  EXPECT_THROW(mr.control_points(-1), std::out_of_range);
  EXPECT_NO_THROW(mr.details(1));
  EXPECT_THROW(mr.details(2), std::out_of_range);
  EXPECT_THROW(mr.reconstruct_finest(3), std::out_of_range);
}

// Reverse subdivision is a least-squares fit, so every coarse curve of a smooth shape stays
// near the finest one instead of cutting corners like a decimated control polygon would. The
// measure is |coarse(u) - fine(2^k u)| at equal parameters: an upper bound of the distance
// from the coarse curve to the fine one, with no discretisation of either curve.
TEST(Multiresolution, CoarseCurvesStayCloseToTheFineOne) {
  const Multiresolution mr(ellipse_points(256), 5);  // down to 8 control points
  const PeriodicBSpline fine(mr.control_points(0));
  // Measured on the ellipse with semi-axes 2 and 1 (m): 4.9e-8, 8.3e-7, 1.3e-5, 1.9e-4 and
  // 2.2e-3 for 128, 64, 32, 16 and 8 control points (the error falls 16-fold per level, as a
  // fourth-order fit should). Bounds: the measures times about 1.5.
  const std::array<double, 5> bound = {7.5e-8, 1.25e-6, 2e-5, 3e-4, 3.3e-3};
  for (int k = 1; k <= 5; ++k) {
    const PeriodicBSpline coarse(mr.control_points(k));
    const double pieces = static_cast<double>(1 << k);
    double worst = 0.0;
    for (int s = 0; s < 2048; ++s) {
      const double u = static_cast<double>(coarse.size()) * (s + 0.5) / 2048.0;
      worst = std::max(worst, (coarse.point_at(u) - fine.point_at(u * pieces)).norm());
    }
    EXPECT_LE(worst, bound[static_cast<std::size_t>(k - 1)]) << "level " << k;
  }
}

// Mean over the parameter of the squared normal deviation of a level-k curve from the clean
// one at the same place: to first order in the noise, the squared distance to the clean shape.
double mean_square_normal_deviation(const std::vector<Vec2>& coarse, int level,
                                    const PeriodicBSpline& clean) {
  const PeriodicBSpline curve(coarse);
  const double pieces = static_cast<double>(1 << level);
  constexpr int kSamples = 2048;
  double sum = 0.0;
  for (int s = 0; s < kSamples; ++s) {
    const double u = static_cast<double>(curve.size()) * (s + 0.5) / kSamples;
    const Vec2 normal = perp(clean.derivative_at(u * pieces)).normalized();
    const double deviation = (curve.point_at(u) - clean.point_at(u * pieces)).dot(normal);
    sum += deviation * deviation;
  }
  return sum / kSamples;
}

// White noise on the control points: what one and two analysis steps keep of it, against the
// closed forms of the filters (traces of the periodic operators, computed once with rational
// arithmetic). Per coordinate, in units of sigma^2:
// - control polygon S A f (the coarse curve on the fine knots): 0.6319 after one level, 0.6815
//   after two, against 1 for the noisy polygon: the coarse levels smooth the control points;
// - the curves themselves (mean over the parameter): 0.4794 for the fine curve, 0.4911 and
//   0.6454 for the coarse ones. A cubic B-spline already averages its control points, and the
//   local filter's negative weights (its coarse points carry 1.80 sigma^2) give some of the
//   noise back, so the coarse curves are not closer to the noise-free shape than the fine one.
TEST(Multiresolution, CoarseLevelsKeepTheClosedFormShareOfNoise) {
  const auto clean_points = ellipse_points(256);
  const PeriodicBSpline clean(clean_points);
  constexpr double kSigma = 0.01;  // m, about 1/5 of the control point spacing
  constexpr int kSeeds = 32;
  std::array<double, 3> polygon{}, curve{};  // mean squares for levels 0, 1, 2
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    Rng rng(100 + seed);
    auto noisy = clean_points;
    for (Vec2& p : noisy)
      p += kSigma * Vec2(rng.normal(), rng.normal());
    const Multiresolution mr(noisy, 2);
    for (int k = 0; k <= 2; ++k) {
      // Level k on the finest knots: its control points subdivided back, details dropped.
      auto on_fine_knots = mr.control_points(k);
      for (int j = 0; j < k; ++j)
        on_fine_knots = subdivide_control_points(on_fine_knots);
      double squares = 0.0;
      for (std::size_t i = 0; i < clean_points.size(); ++i)
        squares += (on_fine_knots[i] - clean_points[i]).squaredNorm();
      const auto index = static_cast<std::size_t>(k);
      polygon[index] += squares / (2.0 * static_cast<double>(clean_points.size())) / kSeeds;
      curve[index] += mean_square_normal_deviation(mr.control_points(k), k, clean) / kSeeds;
    }
  }
  const double var = kSigma * kSigma;
  // Measured: polygon 1.003, 0.641, 0.698; curves 0.475, 0.485, 0.646 (sigma^2). 32 draws of
  // 512 coordinates pin each figure to about 3%; the tolerances are 8%.
  EXPECT_NEAR(polygon[0] / var, 1.0, 0.08);
  EXPECT_NEAR(polygon[1] / var, 0.6319, 0.08 * 0.6319);
  EXPECT_NEAR(polygon[2] / var, 0.6815, 0.08 * 0.6815);
  EXPECT_NEAR(curve[0] / var, 0.4794, 0.08 * 0.4794);
  EXPECT_NEAR(curve[1] / var, 0.4911, 0.08 * 0.4911);
  EXPECT_NEAR(curve[2] / var, 0.6454, 0.08 * 0.6454);
  EXPECT_LT(polygon[1], 0.8 * polygon[0]);
}

}  // namespace
}  // namespace rugosim
