#include "engine/collision/circle_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/collision/polynomial_range.h"

namespace rugosim {
namespace {

constexpr double kNoBound = -std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// P(t) = ‖x(t) − c‖², a sextic in t: with x − c = q0 + q1 t + q2 t² + q3 t³, the coefficient
// of t^k is the sum of q_i·q_j over i + j = k. `rounding` is what evaluating it on [0, 1] may be
// off by: Horner's and the coefficients' own rounding, and q0's (p0 − c, of larger numbers).
struct SquaredDistance {
  Polynomial6 p{};
  double rounding = 0.0;  // m²
};
SquaredDistance squared_distance_to(const CubicSegment& x, const Vec2& c) {
  const auto& k = x.power();
  const std::array<Vec2, 4> q{Vec2(k[0] - c), k[1], k[2], k[3]};
  SquaredDistance out;
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j)
      out.p[i + j] += q[i].dot(q[j]);
  }
  // The coefficients' errors scale with the products they sum, (Σ|q_i|)² at most, whatever
  // cancels in them.
  double reach = 0.0;
  for (const Vec2& v : q)
    reach += v.norm();
  out.rounding = 32.0 * kEpsilon *
                 (reach * reach + 2.0 * q[0].norm() * (k[0].cwiseAbs().sum() + c.cwiseAbs().sum()));
  return out;
}

struct Side {
  const CubicSegment* piece = nullptr;
  double lo = 0.0;  // interval
  double hi = 0.0;
};

// The bound with `inner` in the disk about c and `outer` outside it: the exact extremes of the
// squared distances to c over the intervals, widened by their rounding (which the square roots
// would magnify where a distance is near zero).
double bound_with(const Side& inner, const Side& outer, const Vec2& c) {
  const SquaredDistance in = squared_distance_to(*inner.piece, c);
  const SquaredDistance out = squared_distance_to(*outer.piece, c);
  const double farthest_inner = polynomial_range(in.p, 6, inner.lo, inner.hi).hi + in.rounding;
  const double nearest_outer = polynomial_range(out.p, 6, outer.lo, outer.hi).lo - out.rounding;
  return std::sqrt(std::max(0.0, nearest_outer)) - std::sqrt(farthest_inner);
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
  const Side side_a{&a, s0, s1};
  const Side side_b{&b, t0, t1};
  if (b_inside) return bound_with(side_b, side_a, Vec2(pb - radius * n));
  return bound_with(side_a, side_b, Vec2(pa + radius * n));
}

}  // namespace rugosim
