// Boundary noise (boundary_noise.h): variance 1/2 along the boundary (less the share of the
// octaves not drawn), periodic, and leaving out the finest octaves takes away exactly their
// share and nothing else.
#include "render/draw/boundary_noise.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

constexpr BoundaryNoiseSpec kSpec{.period = 100.0, .correlation_length = 0.05, .octaves = 4};

// The variance of octaves k and up: octave k's strength² is 2^(−1.6k) of the first's, and
// the strengths are normalised over the unending series (variance 1/2 in all).
double share_from(int k) {
  return 0.5 * std::exp2(-1.6 * k);
}

double mean_square(const BoundaryNoise& noise, double period) {
  const int n = 400000;
  double sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = noise(period * i / n);
    sum2 += v * v;
  }
  return sum2 / n;
}

TEST(BoundaryNoise, HasVarianceOneHalfAlongTheBoundary) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const BoundaryNoise noise(kSpec, seed, 0.0);
    ASSERT_EQ(noise.octaves_drawn(), 4);
    EXPECT_NEAR(mean_square(noise, kSpec.period) / (0.5 - share_from(4)), 1.0, 0.05)
        << seed;  // 2000 coarse cells
  }
  // Every octave down to a 1 mm lattice: all but 2^(−9.6) of the unending series.
  for (const std::uint64_t seed : {1u, 2u}) {
    const BoundaryNoise noise({.period = 100.0, .correlation_length = 0.05}, seed, 1e-4);
    ASSERT_EQ(noise.octaves_drawn(), 9);
    EXPECT_NEAR(mean_square(noise, 100.0) / 0.5, 1.0, 0.05) << seed;
  }
}

TEST(BoundaryNoise, IsPeriodicAndContinuous) {
  const BoundaryNoise noise(kSpec, 4, 0.0);
  for (const double s : {0.0, 0.013, 17.5, 99.99}) {
    EXPECT_NEAR(noise(s), noise(s + kSpec.period), 1e-12) << s;
    EXPECT_NEAR(noise(s), noise(s - kSpec.period), 1e-12) << s;
    EXPECT_NEAR(noise(s), noise(s + 1e-9), 1e-5) << s;  // C² B-splines: no jumps
  }
}

// Leaving out the finest of four octaves removes its share of the variance and leaves the
// others exactly as they were.
TEST(BoundaryNoise, LeavingOutTheFinestOctaveChangesNoOther) {
  const BoundaryNoise all(kSpec, 5, 0.0);
  const BoundaryNoise three(kSpec, 5, kSpec.correlation_length / 6.0);  // ℓ/8 is too fine
  ASSERT_EQ(three.octaves_drawn(), 3);
  EXPECT_NEAR(three.finest_spacing(), kSpec.correlation_length / 4.0, 1e-12);
  const int n = 400000;
  double diff2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = kSpec.period * i / n;
    diff2 += std::pow(all(s) - three(s), 2);
  }
  EXPECT_NEAR(diff2 / n / (share_from(3) - share_from(4)), 1.0, 0.05);
}

TEST(BoundaryNoise, ShortBoundariesKeepFourCellsAndHugeLatticesAreLeftOut) {
  const BoundaryNoise small({.period = 0.01, .correlation_length = 1.0, .octaves = 4}, 6, 0.0);
  EXPECT_EQ(small.octaves_drawn(), 4);  // every octave has 4 cells round the boundary
  EXPECT_NEAR(small.finest_spacing(), 0.0025, 1e-15);
  const BoundaryNoise capped({.period = 1e6, .correlation_length = 1.0}, 6, 0.0, 1u << 20);
  EXPECT_EQ(capped.octaves_drawn(), 1);  // 1e6 cells; 2e6 would pass the cap
}

TEST(BoundaryNoise, RejectsNonPositiveLengths) {
  EXPECT_THROW(BoundaryNoise({.period = 0.0, .correlation_length = 1.0}, 1, 0.0),
               std::invalid_argument);
  EXPECT_THROW(BoundaryNoise({.period = 1.0, .correlation_length = -1.0}, 1, 0.0),
               std::invalid_argument);
  EXPECT_THROW(BoundaryNoise({.period = INFINITY, .correlation_length = 1.0}, 1, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
