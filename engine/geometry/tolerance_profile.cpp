#include "engine/geometry/tolerance_profile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rugosim {

namespace {

// Power-basis coefficients of the cubic through (0, y0), (1, y1), (2, y2), (3, y3), from
// Newton's forward differences: p(x) = y0 + d1 x + d2 x(x-1)/2 + d3 x(x-1)(x-2)/6.
std::array<double, 4> cubic_through_nodes(double y0, double y1, double y2, double y3) {
  const double d1 = y1 - y0;
  const double d2 = y2 - 2.0 * y1 + y0;
  const double d3 = y3 - 3.0 * y2 + 3.0 * y1 - y0;
  return {y0, d1 - d2 / 2.0 + d3 / 3.0, d2 / 2.0 - d3 / 2.0, d3 / 6.0};
}

// Lagrange form at x: exact at the nodes (x = 1 returns y1 bit for bit), which the
// power basis would not guarantee.
double lagrange_cubic(double y0, double y1, double y2, double y3, double x) {
  const double a = x, b = x - 1.0, c = x - 2.0, d = x - 3.0;
  return -y0 * (b * c * d) / 6.0 + y1 * (a * c * d) / 2.0 - y2 * (a * b * d) / 2.0 +
         y3 * (a * b * c) / 6.0;
}

}  // namespace

ToleranceProfile ToleranceProfile::from_sigma(std::span<const double> sigma, double q) {
  if (!(q > 0.0 && q <= 1.0)) {
    throw std::invalid_argument("q must be in (0, 1], got " + std::to_string(q));
  }
  std::vector<double> lambda(sigma.size());
  for (std::size_t j = 0; j < sigma.size(); ++j) {
    if (!std::isfinite(sigma[j]) || sigma[j] < 0.0) {
      throw std::invalid_argument("sigma of segment " + std::to_string(j) +
                                  " must be finite and >= 0, got " + std::to_string(sigma[j]));
    }
    lambda[j] = q * sigma[j];
  }
  return ToleranceProfile(std::move(lambda));
}

ToleranceProfile::ToleranceProfile(std::vector<double> segment_tolerances)
    : lambda_(std::move(segment_tolerances)) {
  if (lambda_.empty()) throw std::invalid_argument("a tolerance profile needs a segment");
  for (std::size_t j = 0; j < lambda_.size(); ++j) {
    if (!std::isfinite(lambda_[j]) || lambda_[j] < 0.0) {
      throw std::invalid_argument("tolerance of segment " + std::to_string(j) +
                                  " must be finite and >= 0, got " + std::to_string(lambda_[j]));
    }
  }
  homogeneous_ =
      std::all_of(lambda_.begin(), lambda_.end(), [&](double l) { return l == lambda_.front(); });
}

double ToleranceProfile::at(std::size_t j, double t) const {
  if (homogeneous_) return lambda_.front();
  const std::size_t n = lambda_.size();
  // r names the second node of the stencil; nodes r-1, r, r+1, r+2 sit at x = 0, 1, 2, 3.
  const std::size_t r = t < 0.5 ? (j + n - 1) % n : j;
  const double x = t < 0.5 ? t + 1.5 : t + 0.5;  // erratum: t + 1/2, not t + 1
  const double value = lagrange_cubic(lambda_[(r + n - 1) % n], lambda_[r], lambda_[(r + 1) % n],
                                      lambda_[(r + 2) % n], x);
  return std::max(0.0, value);
}

ToleranceRange ToleranceProfile::piece_range(std::size_t r, double x_lo, double x_hi) const {
  const std::size_t n = lambda_.size();
  const auto c = cubic_through_nodes(lambda_[(r + n - 1) % n], lambda_[r], lambda_[(r + 1) % n],
                                     lambda_[(r + 2) % n]);
  auto value = [&](double x) { return std::max(0.0, c[0] + x * (c[1] + x * (c[2] + x * c[3]))); };
  ToleranceRange range{value(x_lo), value(x_lo)};
  auto include = [&](double v) {
    range.lo = std::min(range.lo, v);
    range.hi = std::max(range.hi, v);
  };
  include(value(x_hi));
  // The nodes are exact in Lagrange form; the power basis may round them.
  if (x_lo == 1.0) include(lambda_[r]);
  if (x_hi == 2.0) include(lambda_[(r + 1) % n]);
  // Interior extrema: roots of p'(x) = c1 + 2 c2 x + 3 c3 x^2 inside (x_lo, x_hi).
  const double qa = 3.0 * c[3], qb = 2.0 * c[2], qc = c[1];
  std::array<double, 2> roots{};
  std::size_t root_count = 0;
  if (qa == 0.0) {
    if (qb != 0.0) roots[root_count++] = -qc / qb;
  } else {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      // Numerically stable pair of roots.
      const double s = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (s != 0.0) roots[root_count++] = qc / s;
      roots[root_count++] = s / qa;
    }
  }
  for (std::size_t k = 0; k < root_count; ++k) {
    if (roots[k] > x_lo && roots[k] < x_hi) include(value(roots[k]));
  }
  return range;
}

ToleranceRange ToleranceProfile::segment_range(std::size_t j) const {
  if (homogeneous_) return {lambda_.front(), lambda_.front()};
  const std::size_t n = lambda_.size();
  // t in [0, 1/2] is piece j-1 at x in [3/2, 2]; t in [1/2, 1] is piece j at x in [1, 3/2].
  const ToleranceRange first = piece_range((j + n - 1) % n, 1.5, 2.0);
  const ToleranceRange second = piece_range(j, 1.0, 1.5);
  return {std::min(first.lo, second.lo), std::max(first.hi, second.hi)};
}

ToleranceRange ToleranceProfile::range() const {
  if (homogeneous_) return {lambda_.front(), lambda_.front()};
  ToleranceRange range = piece_range(0, 1.0, 2.0);
  for (std::size_t r = 1; r < lambda_.size(); ++r) {
    const ToleranceRange piece = piece_range(r, 1.0, 2.0);
    range.lo = std::min(range.lo, piece.lo);
    range.hi = std::max(range.hi, piece.hi);
  }
  return range;
}

}  // namespace rugosim
