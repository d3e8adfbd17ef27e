#include "engine/collision/circle_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rugosim {
namespace {

constexpr double kNoBound = -std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

struct Range {
  double lo = 0.0;
  double hi = 0.0;
};

// Range over [lo, hi] of P''(t)/2 = ‖x'(t)‖² + (x(t) − c)·x''(t), a quartic, bounded by its
// Bernstein coefficients on the interval (the polynomial lies in their convex hull).
Range half_second_derivative_range(const CubicSegment& x, const Vec2& c, double lo, double hi) {
  const auto& p = x.power();
  const Vec2 q0 = p[0] - c;
  // (x − c)·x'' + x'·x' in powers of t: x − c = q0 + p1 t + p2 t² + p3 t³, x' = p1 + 2p2 t +
  // 3p3 t², x'' = 2p2 + 6p3 t.
  std::array<double, 5> g{};
  g[0] = 2.0 * q0.dot(p[2]) + p[1].dot(p[1]);
  g[1] = 6.0 * q0.dot(p[3]) + 2.0 * p[1].dot(p[2]) + 4.0 * p[1].dot(p[2]);
  g[2] = 6.0 * p[1].dot(p[3]) + 2.0 * p[2].dot(p[2]) + 6.0 * p[1].dot(p[3]) + 4.0 * p[2].dot(p[2]);
  g[3] = 6.0 * p[2].dot(p[3]) + 2.0 * p[2].dot(p[3]) + 12.0 * p[2].dot(p[3]);
  g[4] = 6.0 * p[3].dot(p[3]) + 9.0 * p[3].dot(p[3]);
  // Taylor shift to t = lo + h·u, u in [0, 1].
  for (int k = 0; k < 4; ++k) {
    for (int j = 3; j >= k; --j)
      g[static_cast<std::size_t>(j)] += lo * g[static_cast<std::size_t>(j) + 1];
  }
  const double h = hi - lo;
  double scale = 1.0;
  for (double& coefficient : g) {
    coefficient *= scale;
    scale *= h;
  }
  const std::array<double, 5> bernstein{
      g[0],
      g[0] + g[1] / 4.0,
      g[0] + g[1] / 2.0 + g[2] / 6.0,
      g[0] + 0.75 * g[1] + 0.5 * g[2] + 0.25 * g[3],
      g[0] + g[1] + g[2] + g[3] + g[4],
  };
  const auto [low, high] = std::minmax_element(bernstein.begin(), bernstein.end());
  // Rounding of the sums, relative to the largest term.
  double magnitude = 0.0;
  for (const double coefficient : g)
    magnitude += std::abs(coefficient);
  const double slack = 32.0 * kEpsilon * magnitude;
  return {*low - slack, *high + slack};
}

struct Side {
  const CubicSegment* piece = nullptr;
  double ref = 0.0;  // reference parameter
  double lo = 0.0;   // interval
  double hi = 0.0;
};

// P(x) = ‖x − c‖² at the reference and its first-order reach over the interval: a concave P is
// at most value + reach, a convex one at least value − reach.
struct Tangent {
  double value = 0.0;
  double reach = 0.0;
};
Tangent tangent(const Side& side, const Vec2& c) {
  const Vec2 r = side.piece->point(side.ref) - c;
  const double slope = 2.0 * r.dot(side.piece->derivative(side.ref));
  const double span = std::max(side.ref - side.lo, side.hi - side.ref);
  return {r.squaredNorm(), std::abs(slope) * span};
}

// The bound with `inner` in the disk about c and `outer` outside it.
double bound_with(const Side& inner, const Side& outer, const Vec2& c) {
  if (half_second_derivative_range(*inner.piece, c, inner.lo, inner.hi).hi >= 0.0) return kNoBound;
  if (half_second_derivative_range(*outer.piece, c, outer.lo, outer.hi).lo <= 0.0) return kNoBound;
  const Tangent in = tangent(inner, c);
  const Tangent out = tangent(outer, c);
  const double bound =
      std::sqrt(std::max(0.0, out.value - out.reach)) - std::sqrt(in.value + in.reach);
  // Rounding of the squared radii, which are evaluated far from zero when the circle is large.
  const double radius = std::sqrt(out.value);
  return bound - 64.0 * kEpsilon * (radius + c.norm());
}

}  // namespace

double circle_separation_bound(const CubicSegment& a, const CubicSegment& b, double s_ref,
                               double t_ref, double s0, double s1, double t0, double t1) {
  const Vec2 pa = a.point(s_ref);
  const Vec2 pb = b.point(t_ref);
  const Vec2 r = pa - pb;
  const double d = r.norm();
  if (!(d > 0.0) || !std::isfinite(d)) return kNoBound;
  const Vec2 n = r / d;  // from B towards A
  const Vec2 da = a.derivative(s_ref);
  const Vec2 db = b.derivative(t_ref);
  const double speed_a = da.squaredNorm();
  const double speed_b = db.squaredNorm();
  if (!(speed_a > 0.0) || !(speed_b > 0.0)) return kNoBound;
  // Curvature of each piece bending away from the other (1/m): positive for a bump facing the
  // other piece, negative for a dent.
  const double bend_a = n.dot(a.second_derivative(s_ref)) / speed_a;
  const double bend_b = -n.dot(b.second_derivative(t_ref)) / speed_b;
  // The more curved bump goes inside; the circle's curvature lies between its bend and the
  // other piece's bend towards it (the geometric mean when that one is a dent, else half).
  const bool b_inside = bend_b >= bend_a;
  const double inner_bend = b_inside ? bend_b : bend_a;
  const double outer_towards = -(b_inside ? bend_a : bend_b);
  if (!(inner_bend > 0.0) || outer_towards >= inner_bend) return kNoBound;
  const double curvature =
      outer_towards > 0.0 ? std::sqrt(inner_bend * outer_towards) : 0.5 * inner_bend;
  const double radius = 1.0 / curvature;
  if (!std::isfinite(radius)) return kNoBound;
  const Side side_a{&a, s_ref, s0, s1};
  const Side side_b{&b, t_ref, t0, t1};
  if (b_inside) return bound_with(side_b, side_a, Vec2(pb - radius * n));
  return bound_with(side_a, side_b, Vec2(pa + radius * n));
}

}  // namespace rugosim
