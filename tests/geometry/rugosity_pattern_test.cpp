#include "engine/geometry/rugosity_pattern.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

TEST(RugosityPattern, NamesRoundTrip) {
  for (const char* name : {"type_1", "type_2", "type_3", "type_4"}) {
    const auto pattern = parse_rugosity_pattern(name);
    ASSERT_TRUE(pattern.has_value()) << name;
    EXPECT_EQ(rugosity_pattern_name(*pattern), name);
  }
  EXPECT_FALSE(parse_rugosity_pattern("type_5").has_value());
  EXPECT_FALSE(parse_rugosity_pattern("Type_1").has_value());
}

TEST(RugosityPattern, EveryPatternStaysBetweenTheSmoothShareAndSigma) {
  for (auto pattern : {RugosityPattern::kConstant, RugosityPattern::kGradient,
                       RugosityPattern::kRandom, RugosityPattern::kPatches}) {
    for (std::size_t n : {4u, 5u, 16u, 33u, 100u, 1024u}) {
      const auto sigma = pattern_sigmas(pattern, 0.02, n, 9);
      ASSERT_EQ(sigma.size(), n);
      for (double s : sigma) {
        EXPECT_GE(s, 0.02 * kPatternSmoothShare - 1e-15);
        EXPECT_LE(s, 0.02);
      }
    }
  }
}

TEST(RugosityPattern, ConstantIsConstant) {
  const auto sigma = pattern_sigmas(RugosityPattern::kConstant, 0.01, 40, 0);
  EXPECT_TRUE(std::all_of(sigma.begin(), sigma.end(), [](double s) { return s == 0.01; }));
}

TEST(RugosityPattern, GradientIsSmoothAndSpansTheRange) {
  const std::size_t n = 64;
  const auto sigma = pattern_sigmas(RugosityPattern::kGradient, 1.0, n, 0);
  const auto [lo, hi] = std::minmax_element(sigma.begin(), sigma.end());
  EXPECT_NEAR(*lo, kPatternSmoothShare, 0.01);
  EXPECT_NEAR(*hi, 1.0, 0.01);
  for (std::size_t j = 0; j < n; ++j) {
    // Neighbours differ by at most the largest slope of the cosine ramp times the step.
    EXPECT_LE(std::abs(sigma[j] - sigma[(j + 1) % n]), 0.9 * M_PI / n + 1e-12);
  }
}

TEST(RugosityPattern, RandomIsSeededAndNonHomogeneous) {
  const auto a = pattern_sigmas(RugosityPattern::kRandom, 1.0, 200, 5);
  const auto b = pattern_sigmas(RugosityPattern::kRandom, 1.0, 200, 5);
  const auto c = pattern_sigmas(RugosityPattern::kRandom, 1.0, 200, 6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double mean = 0.0;
  for (double s : a)
    mean += s / 200.0;
  EXPECT_NEAR(mean, 0.55, 0.05);  // uniform on [0.1, 1)
}

TEST(RugosityPattern, PatchesAlternateInEqualRuns) {
  const auto sigma = pattern_sigmas(RugosityPattern::kPatches, 1.0, 64, 0);
  // 64 segments -> 8 patches of 8: rough, smooth, rough, ...
  for (std::size_t j = 0; j < 64; ++j) {
    EXPECT_EQ(sigma[j], (j / 8) % 2 == 0 ? 1.0 : kPatternSmoothShare) << j;
  }
  const auto tiny = pattern_sigmas(RugosityPattern::kPatches, 1.0, 4, 0);
  EXPECT_EQ(tiny, (std::vector<double>{1.0, 1.0, kPatternSmoothShare, kPatternSmoothShare}));
}

TEST(RugosityPattern, RejectsBadSigmaAndEmptyBoundaries) {
  EXPECT_THROW(pattern_sigmas(RugosityPattern::kConstant, -1.0, 8, 0), std::invalid_argument);
  EXPECT_THROW(pattern_sigmas(RugosityPattern::kConstant, NAN, 8, 0), std::invalid_argument);
  EXPECT_THROW(pattern_sigmas(RugosityPattern::kConstant, 1.0, 0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
