#include "engine/geometry/universal_threshold.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/multiresolution.h"

namespace rugosim {
namespace {

constexpr std::size_t kPoints = 256;
constexpr double kRadius = 1.0;  // m

// n control points on a circle, each displaced along its normal by sigma times a standard
// normal draw: the paper's rugosity model (§2.2).
std::vector<Vec2> noisy_circle(std::size_t n, double sigma, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const Vec2 normal(std::cos(angle), std::sin(angle));
    points[i] = (kRadius + sigma * rng.normal()) * normal;
  }
  return points;
}

TEST(UniversalThreshold, RejectsCountsWithoutAWaveletLevel) {
  for (std::size_t n : {4u, 6u, 7u, 9u}) {
    const std::vector<Vec2> points = noisy_circle(n, 0.0, 1);
    EXPECT_THROW(estimate_universal_threshold(points), std::invalid_argument) << "n = " << n;
  }
  EXPECT_NO_THROW(estimate_universal_threshold(noisy_circle(8, 0.0, 1)));
}

// The gain is the norm of the detail filter: decompose impulses and sum the squared weights.
TEST(UniversalThreshold, DetailNoiseGainIsTheDetailFilterNorm) {
  constexpr std::size_t kFine = 16;
  double sum = 0.0;
  for (std::size_t k = 0; k < kFine; ++k) {
    std::vector<Vec2> impulse(kFine, Vec2::Zero());
    impulse[k].x() = 1.0;
    const double weight = decompose(impulse).details[3].x();
    sum += weight * weight;
  }
  EXPECT_NEAR(std::sqrt(sum), kDetailNoiseGain, 1e-15);
  EXPECT_NEAR(kDetailNoiseGain * kDetailNoiseGain, 35.0 / 8.0, 1e-14);
}

TEST(UniversalThreshold, SmoothCircleHasNearlyNoNoise) {
  const UniversalThreshold t = estimate_universal_threshold(noisy_circle(kPoints, 0.0, 1));
  EXPECT_EQ(t.coefficient_count, kPoints / 2);
  // The details of a smooth curve are its fourth-order residue: measured 6.4e-8 of the radius.
  EXPECT_LE(t.sigma, 1e-6 * kRadius);
  EXPECT_GE(t.sigma, 0.0);
}

TEST(UniversalThreshold, LambdaIsThePaperFormula) {
  const UniversalThreshold t = estimate_universal_threshold(noisy_circle(kPoints, 1e-3, 2));
  const double m = static_cast<double>(kPoints / 2);
  EXPECT_DOUBLE_EQ(t.lambda, t.sigma * std::sqrt(2.0 * std::log(m)) / std::sqrt(m));
}

// Over many noise draws the estimate is unbiased within a few percent, and no single draw of
// 128 coefficients is off by more than the stated factor.
TEST(UniversalThreshold, RecoversTheNormalNoiseScale) {
  constexpr double kSigma = 1e-3;  // m
  constexpr int kDraws = 40;
  double mean = 0.0, lowest = 1e300, highest = 0.0;
  for (int s = 0; s < kDraws; ++s) {
    const auto points = noisy_circle(kPoints, kSigma, 1000 + static_cast<std::uint64_t>(s));
    const double ratio = estimate_universal_threshold(points).sigma / kSigma;
    mean += ratio / kDraws;
    lowest = std::min(lowest, ratio);
    highest = std::max(highest, ratio);
  }
  // Measured: mean 1.005, single draws between 0.80 and 1.34.
  EXPECT_NEAR(mean, 1.0, 0.05);
  EXPECT_GE(lowest, 0.6);
  EXPECT_LE(highest, 1.5);
}

TEST(UniversalThreshold, IsProportionalToTheNoise) {
  // The same draws scaled: the estimate scales with them. Not exactly: the normals come from
  // the noisy coarse curve, whose tilt (about sigma / spacing) mixes in second-order terms.
  const double one = estimate_universal_threshold(noisy_circle(kPoints, 1e-3, 7)).sigma;
  const double two = estimate_universal_threshold(noisy_circle(kPoints, 2e-3, 7)).sigma;
  EXPECT_NEAR(two / one, 2.0, 1e-2);  // measured 1.997
  // Independent draws: doubling sigma doubles the mean estimate within 10%.
  double sum_one = 0.0, sum_two = 0.0;
  for (std::uint64_t s = 0; s < 20; ++s) {
    sum_one += estimate_universal_threshold(noisy_circle(kPoints, 1e-3, 200 + s)).sigma;
    sum_two += estimate_universal_threshold(noisy_circle(kPoints, 2e-3, 300 + s)).sigma;
  }
  EXPECT_NEAR(sum_two / sum_one, 2.0, 0.2);  // measured 2.05
}

// A few large features (bumps of 50 sigma) barely move the median-based estimate, while the
// root mean square of the same details grows several-fold.
TEST(UniversalThreshold, IsRobustToAFewLargeFeatures) {
  constexpr double kSigma = 1e-3;  // m
  auto points = noisy_circle(kPoints, kSigma, 9);
  const auto rms_detail = [](const std::vector<Vec2>& p) {
    double sum = 0.0;
    for (const Vec2& d : decompose(p).details)
      sum += d.squaredNorm();
    return std::sqrt(sum / static_cast<double>(p.size() / 2));
  };
  const double plain = estimate_universal_threshold(points).sigma;
  const double plain_rms = rms_detail(points);
  for (std::size_t i = 0; i < kPoints; i += kPoints / 3)
    points[i] *= 1.0 + 50.0 * kSigma;
  const double bumped = estimate_universal_threshold(points).sigma;
  EXPECT_NEAR(bumped / plain, 1.0, 0.15);          // measured 1.08
  EXPECT_GE(rms_detail(points) / plain_rms, 4.0);  // measured 5.3
}

TEST(UniversalThreshold, IgnoresRigidMotion) {
  const auto points = noisy_circle(kPoints, 1e-3, 5);
  const double angle = 0.7;
  Mat2 rotation;
  rotation << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  std::vector<Vec2> moved(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    moved[i] = rotation * points[i] + Vec2(3.0, -4.0);
  const double a = estimate_universal_threshold(points).sigma;
  const double b = estimate_universal_threshold(moved).sigma;
  EXPECT_NEAR(b, a, 1e-9 * a);
}

}  // namespace
}  // namespace rugosim
