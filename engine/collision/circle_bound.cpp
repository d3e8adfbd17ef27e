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
  double ref = 0.0;  // its reference point, in [lo, hi]
};

// The bound with `inner` in the disk about c and `outer` outside it, from the extremes of the
// squared distances to c over the intervals, widened by their rounding (which the square roots
// would magnify where a distance is near zero). First from the Bernstein enclosures split at the
// reference points, which are as tight where the circle touches each piece there only
// (polynomial_range.h) and far cheaper; where that falls short of `needed`, from the exact
// extremes (polynomial_range) of the same polynomials.
double bound_with(const Side& inner, const Side& outer, const Vec2& c, double needed) {
  const SquaredDistance in = squared_distance_to(*inner.piece, c);
  const SquaredDistance out = squared_distance_to(*outer.piece, c);
  const auto bound = [&](const PolynomialRange& in_range, const PolynomialRange& out_range) {
    const double farthest_inner = in_range.hi + in.rounding;
    const double nearest_outer = out_range.lo - out.rounding;
    return std::sqrt(std::max(0.0, nearest_outer)) - std::sqrt(farthest_inner);
  };
  const double quick = bound(polynomial_enclosure(in.p, inner.lo, inner.ref, inner.hi),
                             polynomial_enclosure(out.p, outer.lo, outer.ref, outer.hi));
  if (quick >= needed) return quick;
  return bound(polynomial_range(in.p, 6, inner.lo, inner.hi),
               polynomial_range(out.p, 6, outer.lo, outer.hi));
}

// The circles through a point p of a piece, tangent there to the line across `direction`, with
// centres p + R·direction: a point x of the piece is inside the one of curvature k = 1/R when
// ‖x − p‖² <= 2R·direction·(x − p), that is when k <= 2·direction·(x − p)/‖x − p‖² (never, when
// direction·(x − p) <= 0). Over samples of the piece, and the limit at p itself where p is not an
// end (the piece's own bend there), this gives the largest curvature of a circle that holds the
// whole piece (`holds`) and the smallest of one that leaves it all outside (`clears`). They are
// taken at samples: the bound computed with a circle is exact whatever circle it is, and a
// circle chosen a little off only makes it lower.
struct Fit {
  double holds = std::numeric_limits<double>::infinity();    // 1/m; <= 0: nothing holds it
  double clears = -std::numeric_limits<double>::infinity();  // 1/m
};
Fit fit_circles(const CubicSegment& piece, double at, double lo, double hi, const Vec2& p,
                const Vec2& direction) {
  constexpr int kSamples = 8;
  Fit fit;
  const auto take = [&](double k) {
    fit.holds = std::min(fit.holds, k);
    fit.clears = std::max(fit.clears, k);
  };
  const double speed = piece.derivative(at).squaredNorm();
  for (int i = 0; i <= kSamples; ++i) {
    const Vec2 v = piece.point(lo + (hi - lo) * (static_cast<double>(i) / kSamples)) - p;
    const double v2 = v.squaredNorm();
    // Samples at p say nothing (the limit below stands for them).
    if (!(v2 > 1e-20 * (hi - lo) * (hi - lo) * speed)) continue;
    take(2.0 * direction.dot(v) / v2);
  }
  // The limit at p, along the piece: direction·x''/‖x'‖² (direction is normal to it there).
  if (at > lo && at < hi && speed > 0.0) take(direction.dot(piece.second_derivative(at)) / speed);
  return fit;
}

}  // namespace

double circle_separation_bound(const CubicSegment& a, const CubicSegment& b, double s_ref,
                               double t_ref, double s0, double s1, double t0, double t1,
                               double needed) {
  const Vec2 pa = a.point(s_ref);
  const Vec2 pb = b.point(t_ref);
  const Vec2 r = pa - pb;
  const double d = r.norm();
  if (!(d > 0.0) || !std::isfinite(d)) return kNoBound;
  const Vec2 n = r / d;  // from B towards A
  const Side side_a{&a, s0, s1, s_ref};
  const Side side_b{&b, t0, t1, t_ref};
  // A circle with one piece inside through its reference point and the other outside through
  // its own: with A inside, the centre is pa + R·n and B must clear the circle of radius R + d
  // about it; with B inside, pb − R·n and A must clear R + d. The circle is chosen from the
  // pieces' whole shape (fit_circles), not only their bends at the reference points: a piece of
  // a rough outline bends more or less along its length, and a piece whose reference point is
  // one of its ends (where the nearest points leave the rectangle) needs no bend at all there.
  // Where both fit, the radius between the two limits (their geometric mean) leaves both
  // pieces room; the bound is then the distance itself.
  // Both pieces' fits along n, once: along −n every ratio only changes sign, so what holds a
  // piece there is minus what clears it along n, and the other way round (exactly, in floating
  // point too).
  const Fit fit_a = fit_circles(a, s_ref, s0, s1, pa, n);
  const Fit fit_b = fit_circles(b, t_ref, t0, t1, pb, n);
  double best = kNoBound;
  const auto try_inside = [&](const Side& inner, double holds, const Vec2& p_inner,
                              const Side& outer, double clears, const Vec2& out) {
    // `out` points from the inner piece's reference point towards the centre.
    if (!(holds > 0.0) || !std::isfinite(holds)) return;
    const double r_lo = 1.0 / holds;
    const double r_hi = clears > 0.0 ? 1.0 / clears - d : std::numeric_limits<double>::infinity();
    if (!(r_hi >= r_lo)) return;
    const double radius = std::isfinite(r_hi) ? std::sqrt(r_lo * r_hi) : 2.0 * r_lo;
    best = std::max(best, bound_with(inner, outer, Vec2(p_inner + radius * out), needed));
  };
  try_inside(side_a, fit_a.holds, pa, side_b, fit_b.clears, n);
  if (best < d && best < needed)
    try_inside(side_b, -fit_b.clears, pb, side_a, -fit_a.holds, Vec2(-n));
  return best;
}

}  // namespace rugosim
