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

// An enclosure of the range of a sextic p over [lo, hi] (lo <= mid <= hi, within [0, 1]): the
// extremes of its Bernstein coefficients over [lo, mid] and [mid, hi] (a polynomial lies within
// the hull of its Bernstein coefficients), widened by what converting to them may round (the
// coefficients' own rounding is the caller's, as for polynomial_range). A few dozen products
// where polynomial_range isolates the roots of p' down to a quadratic; and exact up to rounding
// where p is extreme at lo, mid or hi and bends away from there, as the circle certificate's
// squared distances do at its reference points (circle_bound.h).
PolynomialRange polynomial_enclosure(const Polynomial6& p, double lo, double mid, double hi);

}  // namespace rugosim
