#include "engine/collision/bezier_bounds.h"

#include <algorithm>
#include <cmath>

namespace rugosim {
namespace {

// Fraction along q0-q1 of the point nearest p, and its squared distance (one square root per
// bound instead of one per projection: these run several times per rectangle of the search).
std::pair<double, double> project_on_segment(const Vec2& p, const Vec2& q0, const Vec2& q1) {
  const Vec2 d = q1 - q0;
  const double length2 = d.squaredNorm();
  double v = 0.0;
  if (length2 > 0.0) v = std::clamp((p - q0).dot(d) / length2, 0.0, 1.0);
  return {v, (p - (q0 + v * d)).squaredNorm()};
}

}  // namespace

std::pair<BezierPolygon, BezierPolygon> split_in_half(const BezierPolygon& p) {
  const Vec2 m01 = 0.5 * (p[0] + p[1]);
  const Vec2 m12 = 0.5 * (p[1] + p[2]);
  const Vec2 m23 = 0.5 * (p[2] + p[3]);
  const Vec2 m012 = 0.5 * (m01 + m12);
  const Vec2 m123 = 0.5 * (m12 + m23);
  const Vec2 mid = 0.5 * (m012 + m123);
  return {BezierPolygon{p[0], m01, m012, mid}, BezierPolygon{mid, m123, m23, p[3]}};
}

double chord_deviation(const BezierPolygon& p) {
  // Distance to the chord is convex, so over the hull it peaks at a control point; the end
  // points are on the chord.
  return std::sqrt(std::max(project_on_segment(p[1], p[0], p[3]).second,
                            project_on_segment(p[2], p[0], p[3]).second));
}

ChordPair closest_on_chords(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  // Proper crossing: the end points of each segment lie strictly on opposite sides of the
  // other's line. Touching and collinear cases fall through to the projections, which then
  // find a zero distance.
  const double o_p0 = cross(q1 - q0, p0 - q0);
  const double o_p1 = cross(q1 - q0, p1 - q0);
  const double o_q0 = cross(p1 - p0, q0 - p0);
  const double o_q1 = cross(p1 - p0, q1 - p0);
  if (((o_p0 < 0.0 && o_p1 > 0.0) || (o_p0 > 0.0 && o_p1 < 0.0)) &&
      ((o_q0 < 0.0 && o_q1 > 0.0) || (o_q0 > 0.0 && o_q1 < 0.0))) {
    return {o_p0 / (o_p0 - o_p1), o_q0 / (o_q0 - o_q1), 0.0};
  }
  ChordPair best;
  const auto [v0, d0] = project_on_segment(p0, q0, q1);
  best = {0.0, v0, d0};
  const auto [v1, d1] = project_on_segment(p1, q0, q1);
  if (d1 < best.distance) best = {1.0, v1, d1};
  const auto [u0, e0] = project_on_segment(q0, p0, p1);
  if (e0 < best.distance) best = {u0, 0.0, e0};
  const auto [u1, e1] = project_on_segment(q1, p0, p1);
  if (e1 < best.distance) best = {u1, 1.0, e1};
  best.distance = std::sqrt(best.distance);  // squared until here
  return best;
}

std::optional<ChordPair> middle_of_chord_overlap(const Vec2& p0, const Vec2& p1, const Vec2& q0,
                                                 const Vec2& q1) {
  const Vec2 d = p1 - p0;
  const double length2 = d.squaredNorm();
  if (!(length2 > 0.0)) return std::nullopt;
  const double w0 = (q0 - p0).dot(d) / length2;
  const double w1 = (q1 - p0).dot(d) / length2;
  const double lo = std::max(0.0, std::min(w0, w1));
  const double hi = std::min(1.0, std::max(w0, w1));
  if (!(lo <= hi)) return std::nullopt;
  const double u = 0.5 * (lo + hi);
  const auto [v, distance2] = project_on_segment(p0 + u * d, q0, q1);
  return ChordPair{u, v, std::sqrt(distance2)};
}

double cubic_minimum(const std::array<double, 4>& k, double lo, double hi) {
  const auto value = [&k](double x) { return k[0] + x * (k[1] + x * (k[2] + x * k[3])); };
  double low = std::min(value(lo), value(hi));
  const auto consider = [&](double x) {
    // A NaN or infinite root fails the range test, so it is never evaluated.
    if (x > lo && x < hi) low = std::min(low, value(x));
  };
  // Critical points: roots of k1 + 2 k2 x + 3 k3 x², by the cancellation-free quadratic formula.
  const double qa = 3.0 * k[3], qb = 2.0 * k[2], qc = k[1];
  if (qa == 0.0) {
    if (qb != 0.0) consider(-qc / qb);
    return low;
  }
  const double disc = qb * qb - 4.0 * qa * qc;
  if (!(disc >= 0.0)) return low;
  const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
  if (q == 0.0) {
    consider(0.0);
  } else {
    consider(q / qa);
    consider(qc / q);
  }
  return low;
}

double separating_axis_bound(const CubicSegment& a, const CubicSegment& b, const Vec2& n, double s0,
                             double s1, double t0, double t1) {
  const auto& pa = a.power();
  const auto& pb = b.power();
  const std::array<double, 4> ka{n.dot(pa[0]), n.dot(pa[1]), n.dot(pa[2]), n.dot(pa[3])};
  const std::array<double, 4> kb{-n.dot(pb[0]), -n.dot(pb[1]), -n.dot(pb[2]), -n.dot(pb[3])};
  // min n·a − max n·b = min n·a + min (−n)·b.
  return cubic_minimum(ka, s0, s1) + cubic_minimum(kb, t0, t1);
}

}  // namespace rugosim
