// The exact range of a polynomial of low degree over an interval, for the narrow phase's bounds
// (circle_bound.h): its extremes lie at the interval's ends or at roots of its derivative, and
// those are isolated recursively, each root of p' lying where p' is monotonic between two roots
// of p'' (and so on down to a quadratic, solved in closed form), then pinned down by bisection
// safeguarded Newton. No subdivision tolerance: the extremes are exact up to rounding.
#pragma once

#include <array>

namespace rugosim {

// Coefficients of p(x) = c[0] + c[1] x + ... + c[6] x^6 (higher ones zero for a lower degree).
using Polynomial6 = std::array<double, 7>;

struct PolynomialRange {
  double lo = 0.0;
  double hi = 0.0;
};

// The smallest and largest value of the polynomial of the given degree (<= 6) over [lo, hi]
// (the ends in either order).
PolynomialRange polynomial_range(const Polynomial6& p, int degree, double lo, double hi);

}  // namespace rugosim
