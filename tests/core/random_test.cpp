#include "engine/core/random.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

TEST(Rng, SameSeedSameSequence) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    differs |= x != c.next_u64();
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, KnownFirstValuesPinThePlatformIndependentStream) {
  // SplitMix64 from state 0 has published first outputs; pinning them keeps every platform
  // on the same stream (a change here changes every seeded scene).
  std::uint64_t state = 0;
  EXPECT_EQ(splitmix64(state), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(splitmix64(state), 0x6E789E6AA1B965F4ULL);
}

TEST(Rng, UniformMomentsAndRange) {
  Rng rng(7);
  const int count = 200000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < count; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_sq += u * u;
  }
  const double mean = sum / count;
  const double var = sum_sq / count - mean * mean;
  EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / count));
  EXPECT_NEAR(var, 1.0 / 12.0, 2e-3);
}

TEST(Rng, NormalMomentsAndTails) {
  Rng rng(11);
  const int count = 200000;
  double sum = 0.0, sum_sq = 0.0, sum_4 = 0.0;
  int beyond_2 = 0;
  for (int i = 0; i < count; ++i) {
    const double x = rng.normal();
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    sum_sq += x * x;
    sum_4 += x * x * x * x;
    beyond_2 += std::abs(x) > 2.0;
  }
  EXPECT_NEAR(sum / count, 0.0, 4.0 / std::sqrt(count));
  EXPECT_NEAR(sum_sq / count, 1.0, 0.02);
  EXPECT_NEAR(sum_4 / count, 3.0, 0.1);                               // kurtosis of a Gaussian
  EXPECT_NEAR(static_cast<double>(beyond_2) / count, 0.0455, 0.003);  // P(|x| > 2)
}

TEST(DeriveSeed, StreamsAreDistinctAndStable) {
  EXPECT_EQ(derive_seed(5, 1), derive_seed(5, 1));
  EXPECT_NE(derive_seed(5, 1), derive_seed(5, 2));
  EXPECT_NE(derive_seed(5, 1), derive_seed(6, 1));
}

}  // namespace
}  // namespace rugosim
