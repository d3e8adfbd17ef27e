#include "engine/collision/polynomial_range.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

double evaluate(const Polynomial6& p, double x) {
  double v = 0.0;
  for (int k = 6; k >= 0; --k)
    v = v * x + p[static_cast<std::size_t>(k)];
  return v;
}

// Closed forms: (x − ½)² on [0, 1] is 0 at ½ and ¼ at the ends; x³ − x on [−2, 2] has its
// extremes ±2√3/9 at ±1/√3 inside and ±6 at the ends.
TEST(PolynomialRange, ClosedForms) {
  const PolynomialRange square = polynomial_range({0.25, -1.0, 1.0}, 2, 0.0, 1.0);
  EXPECT_NEAR(square.lo, 0.0, 1e-16);
  EXPECT_DOUBLE_EQ(square.hi, 0.25);
  const PolynomialRange cubic = polynomial_range({0.0, -1.0, 0.0, 1.0}, 3, -0.9, 0.9);
  EXPECT_NEAR(cubic.hi, 2.0 * std::sqrt(3.0) / 9.0, 1e-15);
  EXPECT_NEAR(cubic.lo, -2.0 * std::sqrt(3.0) / 9.0, 1e-15);
  // The interval's ends in either order.
  const PolynomialRange reversed = polynomial_range({0.0, -1.0, 0.0, 1.0}, 3, 0.9, -0.9);
  EXPECT_EQ(reversed.lo, cubic.lo);
  EXPECT_EQ(reversed.hi, cubic.hi);
  // A product of sextic roots: (x − 0.1)(x − 0.2)...(x − 0.6), tiny extremes between them.
  Polynomial6 p{1.0};
  for (int r = 1; r <= 6; ++r) {
    Polynomial6 q{};
    for (int k = 0; k < 6; ++k) {
      q[static_cast<std::size_t>(k + 1)] += p[static_cast<std::size_t>(k)];
      q[static_cast<std::size_t>(k)] -= 0.1 * r * p[static_cast<std::size_t>(k)];
    }
    p = q;
  }
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i <= 200000; ++i) {
    const double x = 0.1 + 0.5 * i / 200000.0;
    lo = std::min(lo, evaluate(p, x));
    hi = std::max(hi, evaluate(p, x));
  }
  // Dense sampling lands a little inside the true extremes (second order in its spacing).
  const PolynomialRange range = polynomial_range(p, 6, 0.1, 0.6);
  EXPECT_LE(range.lo, lo);
  EXPECT_GE(range.lo, lo - 1e-9 * std::abs(lo));
  EXPECT_GE(range.hi, hi);
  EXPECT_LE(range.hi, hi + 1e-9 * std::abs(hi));
}

// Property: random polynomials of every degree up to 6 on random intervals contain every sampled
// value, and the range is attained (within the sampling's own error).
TEST(PolynomialRange, ContainsAndMeetsDenseSampling) {
  Rng rng(61);
  for (int c = 0; c < 3000; ++c) {
    const int degree = c % 7;
    Polynomial6 p{};
    for (int k = 0; k <= degree; ++k)
      p[static_cast<std::size_t>(k)] = rng.normal() * std::pow(10.0, rng.uniform(-3.0, 3.0));
    const double lo = rng.uniform(-2.0, 1.0), hi = lo + rng.uniform(1e-3, 2.0);
    const PolynomialRange range = polynomial_range(p, degree, lo, hi);
    double magnitude = 0.0;
    for (const double k : p)
      magnitude += std::abs(k) * 8.0;
    double sampled_lo = 1e300, sampled_hi = -1e300;
    for (int i = 0; i <= 4000; ++i) {
      const double v = evaluate(p, lo + (hi - lo) * i / 4000.0);
      sampled_lo = std::min(sampled_lo, v);
      sampled_hi = std::max(sampled_hi, v);
      ASSERT_GE(v, range.lo - 1e-13 * magnitude) << "case " << c;
      ASSERT_LE(v, range.hi + 1e-13 * magnitude) << "case " << c;
    }
    // Sampling misses the extremes by at most second order in the spacing.
    EXPECT_LE(sampled_lo - range.lo, 1e-5 * magnitude) << "case " << c;
    EXPECT_LE(range.hi - sampled_hi, 1e-5 * magnitude) << "case " << c;
  }
}

// Property: the Bernstein enclosure holds every sampled value of random sextics on random
// intervals within [0, 1], and never reaches beyond the exact range by more than rounding on the
// side where the extreme sits at the split point and p bends away from it.
TEST(PolynomialEnclosure, ContainsTheRangeAndIsExactAtAnExtremeWhereItSplits) {
  Rng rng(62);
  int tight = 0;
  for (int c = 0; c < 3000; ++c) {
    Polynomial6 p{};
    for (double& k : p)
      k = rng.normal() * std::pow(10.0, rng.uniform(-3.0, 3.0));
    const double lo = rng.uniform(0.0, 0.8), hi = lo + rng.uniform(1e-3, 1.0 - lo);
    double mid = rng.uniform(lo, hi);
    if (c % 2 == 0) {
      // A squared distance's shape: p = (x − mid)²·(1 + ...) + p0 has its minimum at mid.
      mid = rng.uniform(lo, hi);
      Polynomial6 q{};
      const double p0 = rng.uniform(0.5, 2.0);
      // (x − mid)² · (1 + e·x)  + p0, e small: minimum p0 at mid, rising on both sides.
      const double e = rng.uniform(-0.2, 0.2);
      const Polynomial6 square{mid * mid, -2.0 * mid, 1.0};
      for (std::size_t k = 0; k < 3; ++k) {
        q[k] += square[k];
        q[k + 1] += e * square[k];
      }
      q[0] += p0;
      p = q;
    }
    const PolynomialRange enclosure = polynomial_enclosure(p, lo, mid, hi);
    const PolynomialRange exact = polynomial_range(p, 6, lo, hi);
    double magnitude = 0.0;
    for (const double k : p)
      magnitude += std::abs(k) * 64.0;
    ASSERT_LE(enclosure.lo, exact.lo + 1e-14 * magnitude) << "case " << c;
    ASSERT_GE(enclosure.hi, exact.hi - 1e-14 * magnitude) << "case " << c;
    for (int i = 0; i <= 1000; ++i) {
      const double v = evaluate(p, lo + (hi - lo) * i / 1000.0);
      ASSERT_GE(v, enclosure.lo) << "case " << c;
      ASSERT_LE(v, enclosure.hi) << "case " << c;
    }
    if (c % 2 == 0) {
      EXPECT_NEAR(enclosure.lo, exact.lo, 1e-13 * magnitude) << "case " << c;
      ++tight;
    }
  }
  EXPECT_EQ(tight, 1500);
}

}  // namespace
}  // namespace rugosim
