#include "engine/collision/polynomial_range.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rugosim {
namespace {

constexpr int kMaxIterations = 100;

double evaluate(const Polynomial6& p, int degree, double x) {
  double value = p[static_cast<std::size_t>(degree)];
  for (int k = degree - 1; k >= 0; --k)
    value = value * x + p[static_cast<std::size_t>(k)];
  return value;
}

Polynomial6 derivative(const Polynomial6& p, int degree) {
  Polynomial6 d{};
  for (int k = 1; k <= degree; ++k)
    d[static_cast<std::size_t>(k - 1)] = static_cast<double>(k) * p[static_cast<std::size_t>(k)];
  return d;
}

// The root of p in [a, b], where p is monotonic and p(a), p(b) differ in sign: bisection, with a
// Newton step taken whenever it lands inside the bracket.
double bracketed_root(const Polynomial6& p, int degree, double a, double b, double fa) {
  const Polynomial6 d = derivative(p, degree);
  double x = 0.5 * (a + b);
  for (int i = 0; i < kMaxIterations; ++i) {
    const double fx = evaluate(p, degree, x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (fa < 0.0)) {
      a = x;
      fa = fx;
    } else {
      b = x;
    }
    if (!(b - a > 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(a) + std::abs(b))))
      break;
    const double slope = evaluate(d, degree - 1, x);
    const double newton = slope != 0.0 ? x - fx / slope : a;
    x = newton > a && newton < b ? newton : 0.5 * (a + b);
  }
  return x;
}

// The roots of p (degree <= 6) strictly inside (lo, hi), ascending, written to `roots`; returns
// how many (at most `degree`).
int roots_inside(const Polynomial6& p, int degree, double lo, double hi, double* roots) {
  while (degree > 0 && p[static_cast<std::size_t>(degree)] == 0.0)
    --degree;
  if (degree <= 0) return 0;  // a constant: no isolated root
  int count = 0;
  const auto keep = [&](double x) {
    if (x > lo && x < hi) roots[count++] = x;
  };
  if (degree == 1) {
    keep(-p[0] / p[1]);
    return count;
  }
  if (degree == 2) {
    const double a = p[2], b = p[1], c = p[0];
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double x1 = q / a, x2 = q != 0.0 ? c / q : x1;
    if (x1 > x2) std::swap(x1, x2);
    keep(x1);
    if (x2 != x1) keep(x2);
    return count;
  }
  // Between consecutive roots of p', p is monotonic: at most one root each.
  double critical[6];
  const int m = roots_inside(derivative(p, degree), degree - 1, lo, hi, critical);
  double a = lo;
  double fa = evaluate(p, degree, a);
  for (int k = 0; k <= m; ++k) {
    const double b = k < m ? critical[k] : hi;
    const double fb = evaluate(p, degree, b);
    if (fb == 0.0) {
      keep(b);
    } else if (fa != 0.0 && (fa < 0.0) != (fb < 0.0)) {
      keep(bracketed_root(p, degree, a, b, fa));
    }
    a = b;
    fa = fb;
  }
  return count;
}

// The Bernstein coefficients of the sextic p over [u0, u1] into `range` (grown to hold them),
// with p(u0 + (u1 − u0)·v) = Σ b_k·C(6,k)·v^k·(1 − v)^(6−k).
void add_bernstein_hull(const Polynomial6& p, double u0, double u1, PolynomialRange& range) {
  // Taylor shift to u0 (repeated synthetic division), then scale by h^j: q(v) = p(u0 + h·v).
  Polynomial6 q = p;
  for (int k = 0; k < 6; ++k) {
    for (int j = 5; j >= k; --j)
      q[static_cast<std::size_t>(j)] += u0 * q[static_cast<std::size_t>(j + 1)];
  }
  const double h = u1 - u0;
  double scale = 1.0;
  for (std::size_t j = 1; j < 7; ++j) {
    scale *= h;
    q[j] *= scale;
  }
  // b_k = Σ_{i <= k} C(k, i) / C(6, i) · q_i.
  static constexpr double kWeight[7][7] = {
      {1, 0, 0, 0, 0, 0, 0},
      {1, 1.0 / 6, 0, 0, 0, 0, 0},
      {1, 2.0 / 6, 1.0 / 15, 0, 0, 0, 0},
      {1, 3.0 / 6, 3.0 / 15, 1.0 / 20, 0, 0, 0},
      {1, 4.0 / 6, 6.0 / 15, 4.0 / 20, 1.0 / 15, 0, 0},
      {1, 5.0 / 6, 10.0 / 15, 10.0 / 20, 5.0 / 15, 1.0 / 6, 0},
      {1, 1, 1, 1, 1, 1, 1},
  };
  for (std::size_t k = 0; k < 7; ++k) {
    double b = 0.0;
    for (std::size_t i = 0; i <= k; ++i)
      b += kWeight[k][i] * q[i];
    range.lo = std::min(range.lo, b);
    range.hi = std::max(range.hi, b);
  }
}

}  // namespace

PolynomialRange polynomial_enclosure(const Polynomial6& p, double lo, double mid, double hi) {
  PolynomialRange range{std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  if (mid > lo) add_bernstein_hull(p, lo, mid, range);
  if (hi > mid) add_bernstein_hull(p, mid, hi, range);
  if (!(hi > lo)) add_bernstein_hull(p, lo, hi, range);
  // What converting may round, on either half: every q_j sums C(k, j)·|p_k|·u0^(k−j)·h^j <=
  // C(k, j)·|p_k| over k (u0, h in [0, 1]) in a dozen roundings, and every b_k at most seven q_j
  // with weights <= 1: 26·ε·Σ 2^k·|p_k|, taken with a margin.
  double magnitude = 0.0;
  for (std::size_t k = 0, power = 1; k < 7; ++k, power *= 2)
    magnitude += static_cast<double>(power) * std::abs(p[k]);
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
  range.lo -= rounding;
  range.hi += rounding;
  return range;
}

PolynomialRange polynomial_range(const Polynomial6& p, int degree, double lo, double hi) {
  if (hi < lo) std::swap(lo, hi);
  PolynomialRange range;
  range.lo = range.hi = evaluate(p, degree, lo);
  const auto consider = [&](double x) {
    const double v = evaluate(p, degree, x);
    range.lo = std::min(range.lo, v);
    range.hi = std::max(range.hi, v);
  };
  consider(hi);
  if (degree >= 2) {
    double critical[6];
    const int m = roots_inside(derivative(p, degree), degree - 1, lo, hi, critical);
    for (int k = 0; k < m; ++k)
      consider(critical[k]);
  }
  return range;
}

}  // namespace rugosim
