#include "engine/geometry/tolerance_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/friction.h"

namespace rugosim {
namespace {

std::vector<double> random_tolerances(Rng& rng, std::size_t n) {
  std::vector<double> lambda(n);
  for (double& l : lambda)
    l = rng.uniform() < 0.2 ? 0.0 : rng.uniform(0.0, 0.01);
  return lambda;
}

TEST(ToleranceProfile, SigmaTimesQ) {
  const std::vector<double> sigma = {0.001, 0.002, 0.004, 0.0};
  const auto profile = ToleranceProfile::from_sigma(sigma, 0.9);
  for (std::size_t j = 0; j < sigma.size(); ++j) {
    EXPECT_DOUBLE_EQ(profile.segment_tolerance(j), 0.9 * sigma[j]);
  }
}

TEST(ToleranceProfile, RejectsBadInput) {
  const std::vector<double> ok = {0.1, 0.2, 0.3, 0.4};
  EXPECT_THROW(ToleranceProfile::from_sigma(ok, 0.0), std::invalid_argument);
  EXPECT_THROW(ToleranceProfile::from_sigma(ok, 1.5), std::invalid_argument);
  EXPECT_THROW(ToleranceProfile::from_sigma(ok, std::nan("")), std::invalid_argument);
  const std::vector<double> negative = {0.1, -0.2, 0.3, 0.4};
  EXPECT_THROW(ToleranceProfile::from_sigma(negative, 0.9), std::invalid_argument);
  const std::vector<double> infinite = {0.1, INFINITY, 0.3, 0.4};
  EXPECT_THROW(ToleranceProfile::from_sigma(infinite, 0.9), std::invalid_argument);
  EXPECT_THROW(ToleranceProfile(std::vector<double>{}), std::invalid_argument);
}

TEST(ToleranceProfile, EqualsSegmentToleranceAtMidpoints) {
  Rng rng(21);
  for (int c = 0; c < 200; ++c) {
    const auto n = static_cast<std::size_t>(4 + rng.uniform() * 200);
    const ToleranceProfile profile(random_tolerances(rng, n));
    for (std::size_t j = 0; j < n; ++j)
      EXPECT_EQ(profile.at(j, 0.5), profile.segment_tolerance(j));
  }
}

TEST(ToleranceProfile, IsContinuousAroundTheWholeBoundary) {
  // Across joints (t = 1 of segment j meets t = 0 of j + 1) and across midpoints, where the
  // interpolation stencil switches: the paper's t + 1 would jump there (DESIGN.md erratum).
  Rng rng(22);
  for (int c = 0; c < 200; ++c) {
    const auto n = static_cast<std::size_t>(4 + rng.uniform() * 200);
    const ToleranceProfile profile(random_tolerances(rng, n));
    const double scale = *std::max_element(profile.segment_tolerances().begin(),
                                           profile.segment_tolerances().end()) +
                         1e-300;
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_NEAR(profile.at(j, 1.0), profile.at((j + 1) % n, 0.0), 1e-14 * scale);
      EXPECT_NEAR(profile.at(j, std::nextafter(0.5, 0.0)), profile.at(j, 0.5), 1e-14 * scale);
    }
    // A fine walk around the boundary never jumps more than the slope allows.
    double previous = profile.at(0, 0.0);
    const int steps = 64;
    for (std::size_t j = 0; j < n; ++j) {
      for (int k = 1; k <= steps; ++k) {
        const double value = profile.at(j, static_cast<double>(k) / steps);
        // |λ'| <= ~3 max λ per unit parameter for this cubic stencil.
        EXPECT_LE(std::abs(value - previous), 4.0 * scale / steps);
        previous = value;
      }
    }
  }
}

TEST(ToleranceProfile, HomogeneousIsConstantAndNeverNegative) {
  const ToleranceProfile flat(std::vector<double>(17, 0.003));
  EXPECT_TRUE(flat.homogeneous());
  for (double t : {0.0, 0.2, 0.5, 0.7, 1.0})
    EXPECT_EQ(flat.at(5, t), 0.003);
  // A step 0,0,0,1 overshoots below zero between the zeros: clamped.
  const ToleranceProfile step({0.0, 0.0, 0.0, 1.0, 1.0, 1.0});
  EXPECT_FALSE(step.homogeneous());
  for (std::size_t j = 0; j < 6; ++j) {
    for (int k = 0; k <= 100; ++k)
      EXPECT_GE(step.at(j, k / 100.0), 0.0);
  }
}

TEST(ToleranceProfile, RangeIsExactAgainstDenseSampling) {
  Rng rng(23);
  for (int c = 0; c < 200; ++c) {
    const auto n = static_cast<std::size_t>(4 + rng.uniform() * 60);
    const ToleranceProfile profile(random_tolerances(rng, n));
    const ToleranceRange range = profile.range();
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t j = 0; j < n; ++j) {
      for (int k = 0; k <= 2000; ++k) {
        const double v = profile.at(j, k / 2000.0);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    // The exact range contains every sample and the samples come within grid error of it.
    EXPECT_LE(range.lo, lo + 1e-15);
    EXPECT_GE(range.hi, hi - 1e-15);
    EXPECT_NEAR(range.lo, lo, 1e-8);
    EXPECT_NEAR(range.hi, hi, 1e-8);
  }
}

TEST(Friction, ZeroBelowThresholdAndLinearAbove) {
  EXPECT_EQ(friction_coefficient(0.001, 0.002, 100.0), 0.0);
  EXPECT_EQ(friction_coefficient(0.002, 0.002, 100.0), 0.0);
  EXPECT_NEAR(friction_coefficient(0.005, 0.002, 100.0), 0.3, 1e-15);
  EXPECT_EQ(contact_friction(0.2, 0.5), 0.5);
  EXPECT_EQ(contact_friction(0.5, 0.2), 0.5);
}

}  // namespace
}  // namespace rugosim
