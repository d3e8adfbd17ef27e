// Seeded random pairs of cubic segments for the narrow-phase property tests, by category:
// the typical nearly straight pieces of a boundary and the hard cases of eq. 3-4 (several
// local minima, minima at ends and corners, near-parallel valleys, degenerate input).
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "engine/collision/bezier_bounds.h"
#include "engine/core/random.h"
#include "engine/geometry/cubic_segment.h"
#include "engine/geometry/shapes.h"

namespace rugosim::testing {

// The segment whose Bézier polygon is b: inverts the B-spline to Bézier map of CubicSegment.
inline CubicSegment segment_from_bezier(const BezierPolygon& b) {
  const Vec2 c1 = 2.0 * b[1] - b[2];
  const Vec2 c2 = 2.0 * b[2] - b[1];
  const Vec2 c0 = 6.0 * b[0] - 4.0 * c1 - c2;
  const Vec2 c3 = 6.0 * b[3] - c1 - 4.0 * c2;
  return CubicSegment(c0, c1, c2, c3);
}

// A straight segment from p to q, parameterised at constant speed.
inline BezierPolygon straight_polygon(const Vec2& p, const Vec2& q) {
  return {p, p + (q - p) / 3.0, p + 2.0 * (q - p) / 3.0, q};
}

enum class PairKind {
  kGeneric,         // control points anywhere in a unit box: loops, cusps, S shapes
  kNearParallel,    // nearly straight, nearly parallel, gap 1e-6..1e-1, sometimes 0
  kNearlyTouching,  // tangent at a chosen point, gap ±1e-6..1e-3; convex or concave side
  kEndpoint,        // nearest points at an end of one segment or at two ends
  kMultiCrossing,   // an S-shaped cubic against a line or an opposite S: 2-3 crossings
  kTypical,         // a 64-segment circle's piece against a box side, placed at random
  kDegenerate,      // points, repeated control points, straight, collinear, touching
  kCount
};

inline const char* pair_kind_name(PairKind kind) {
  static constexpr std::array<const char*, 7> kNames{
      "generic",        "near_parallel", "nearly_touching", "endpoint",
      "multi_crossing", "typical",       "degenerate"};
  return kNames[static_cast<std::size_t>(kind)];
}

struct SegmentPair {
  BezierPolygon a{};
  BezierPolygon b{};
};

inline Vec2 random_point(Rng& rng, double lo, double hi) {
  return {rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

inline BezierPolygon reversed(const BezierPolygon& p) {
  return {p[3], p[2], p[1], p[0]};
}

// A nearly straight piece from (0, 0) to (1, 0) bowing by up to `bow`.
inline BezierPolygon bowed_unit(Rng& rng, double bow) {
  return {Vec2(0.0, 0.0), Vec2(1.0 / 3.0, rng.uniform(-bow, bow)),
          Vec2(2.0 / 3.0, rng.uniform(-bow, bow)), Vec2(1.0, 0.0)};
}

// In a local frame (x along the tangent, y along the normal) a parabola y = k x² whose apex is
// at the origin and at parameter sigma, over a width w.
inline BezierPolygon parabola(double w, double k, double sigma) {
  // y(s) = K (s − σ)² with K = k w², in Bernstein form.
  const double kk = k * w * w;
  const std::array<double, 4> y{kk * sigma * sigma, kk * sigma * sigma - 2.0 * kk * sigma / 3.0,
                                kk * sigma * sigma - 4.0 * kk * sigma / 3.0 + kk / 3.0,
                                kk * (1.0 - sigma) * (1.0 - sigma)};
  BezierPolygon p;
  for (std::size_t i = 0; i < 4; ++i)
    p[i] = Vec2(w * (static_cast<double>(i) / 3.0 - sigma), y[i]);
  return p;
}

// b placed tangent to a at a(s0), offset by gap along the normal, bending away from that normal
// with curvature 2k: on a's convex side (convex-convex contact) or on its concave side with a
// sharper bend (concave-convex contact).
inline BezierPolygon tangent_partner(const BezierPolygon& a_poly, double s0, double gap, Rng& rng,
                                     bool concave_side) {
  const CubicSegment a = segment_from_bezier(a_poly);
  const Vec2 p = a.point(s0);
  Vec2 tangent = a.derivative(s0);
  tangent = tangent.norm() > 0.0 ? Vec2(tangent.normalized()) : Vec2(1.0, 0.0);
  Vec2 normal = perp(tangent);
  const double bend = cross(a.derivative(s0), a.second_derivative(s0));
  // a bends towards +normal when bend > 0: its concave side.
  const bool to_concave = bend > 0.0;
  if (to_concave != concave_side) normal = -normal;
  const double a_curvature =
      std::abs(bend) / std::max(1e-300, std::pow(a.derivative(s0).norm(), 3.0));
  double k = rng.uniform(0.05, 1.0);
  if (concave_side) k = std::max(k, 0.5 * a_curvature * rng.uniform(1.3, 3.0));
  const BezierPolygon local = parabola(rng.uniform(0.3, 1.2), k, rng.uniform(0.05, 0.95));
  BezierPolygon out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = p + (gap + local[i].y()) * normal + local[i].x() * tangent;
  return rng.uniform() < 0.5 ? out : reversed(out);
}

inline SegmentPair degenerate_pair(Rng& rng) {
  const int variant = static_cast<int>(rng.uniform() * 10.0);
  SegmentPair pair;
  switch (variant) {
    case 0: {  // a is a single point
      const Vec2 p = random_point(rng, -1.0, 1.0);
      pair.a = {p, p, p, p};
      pair.b = bowed_unit(rng, 0.2);
      break;
    }
    case 1: {  // both are single points
      const Vec2 p = random_point(rng, -1.0, 1.0), q = random_point(rng, -1.0, 1.0);
      pair.a = {p, p, p, p};
      pair.b = {q, q, q, q};
      break;
    }
    case 2: {  // repeated control points: zero tangent at the ends
      const Vec2 p = random_point(rng, -1.0, 1.0), q = random_point(rng, -1.0, 1.0);
      pair.a = {p, p, q, q};
      const Vec2 b0 = random_point(rng, -1.0, 1.0), b1 = random_point(rng, -1.0, 1.0);
      const Vec2 b2 = random_point(rng, -1.0, 1.0);
      pair.b = {b0, b1, b2, b2};
      break;
    }
    case 3:  // straight segments
      pair.a = straight_polygon(random_point(rng, -1.0, 1.0), random_point(rng, -1.0, 1.0));
      pair.b = straight_polygon(random_point(rng, -1.0, 1.0), random_point(rng, -1.0, 1.0));
      break;
    case 4: {  // overlapping collinear pieces
      pair.a = straight_polygon({0.0, 0.0}, {1.0, 0.0});
      const double x0 = rng.uniform(-0.5, 0.8);
      pair.b = straight_polygon({x0, 0.0}, {x0 + rng.uniform(0.3, 1.0), 0.0});
      if (rng.uniform() < 0.5) pair.b = reversed(pair.b);
      break;
    }
    case 5: {  // an end of b on a (T junction)
      pair.a = bowed_unit(rng, 0.2);
      const Vec2 p = segment_from_bezier(pair.a).point(rng.uniform(0.05, 0.95));
      const double angle = rng.uniform(0.3, std::numbers::pi - 0.3);
      pair.b =
          straight_polygon(p, p + rng.uniform(0.3, 1.0) * Vec2(std::cos(angle), std::sin(angle)));
      break;
    }
    case 6:  // tangent touching
      pair.a = bowed_unit(rng, 0.1);
      pair.b = tangent_partner(pair.a, rng.uniform(0.1, 0.9), 0.0, rng, rng.uniform() < 0.3);
      break;
    case 7:  // identical segments
      pair.a = bowed_unit(rng, 0.2);
      pair.b = pair.a;
      break;
    case 8: {  // straight with repeated inner points, against a point on its line
      pair.a = {Vec2(0.0, 0.0), Vec2(0.5, 0.0), Vec2(0.5, 0.0), Vec2(1.0, 0.0)};
      const Vec2 q(rng.uniform(-1.0, 2.0), 0.0);
      pair.b = {q, q, q, q};
      break;
    }
    default: {  // parallel straight pieces at a gap
      pair.a = straight_polygon({0.0, 0.0}, {1.0, 0.0});
      const double x0 = rng.uniform(-0.5, 0.8), gap = std::pow(10.0, rng.uniform(-6.0, -1.0));
      pair.b = straight_polygon({x0, gap}, {x0 + rng.uniform(0.3, 1.0), gap});
      break;
    }
  }
  return pair;
}

inline SegmentPair typical_pair(Rng& rng) {
  // A piece of a 64-segment circle of radius 1 against a straight box side of similar length.
  static const std::vector<Vec2> circle = circle_control_points(1.0, 64);
  const std::size_t n = circle.size();
  const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(n));
  const CubicSegment arc(circle[(j + n - 1) % n], circle[j], circle[(j + 1) % n],
                         circle[(j + 2) % n]);
  const double length = (arc.bezier()[3] - arc.bezier()[0]).norm();
  const Vec2 p = arc.point(rng.uniform());
  const Vec2 out = p.normalized();
  const double u = rng.uniform();
  double gap = length * rng.uniform(-0.05, 0.05);
  if (u < 0.3) gap = length * std::pow(10.0, rng.uniform(-6.0, -2.0));
  const double tilt = rng.uniform(-0.2, 0.2);
  const Vec2 along = Vec2(-out.y(), out.x()) * std::cos(tilt) + out * std::sin(tilt);
  const Vec2 centre = p + gap * out + rng.uniform(-0.5, 0.5) * length * along;
  const double half = 0.5 * length * rng.uniform(0.5, 2.0);
  SegmentPair pair{arc.bezier(), straight_polygon(centre - half * along, centre + half * along)};
  if (rng.uniform() < 0.5) pair.b = reversed(pair.b);
  return pair;
}

inline SegmentPair unit_pair(Rng& rng, PairKind kind) {
  SegmentPair pair;
  switch (kind) {
    case PairKind::kGeneric:
      for (std::size_t i = 0; i < 4; ++i) {
        pair.a[i] = random_point(rng, -1.0, 1.0);
        pair.b[i] = random_point(rng, -1.0, 1.0);
      }
      break;
    case PairKind::kNearParallel: {
      pair.a = bowed_unit(rng, rng.uniform() < 0.2 ? 0.0 : 0.05);
      const BezierPolygon shape = bowed_unit(rng, rng.uniform() < 0.2 ? 0.0 : 0.05);
      const double angle = rng.uniform() < 0.25 ? 0.0 : rng.uniform(-1e-3, 1e-3);
      const double length = rng.uniform(0.5, 1.5);
      double gap = (rng.uniform() < 0.5 ? 1.0 : -1.0) * std::pow(10.0, rng.uniform(-6.0, -1.0));
      if (rng.uniform() < 0.125) gap = 0.0;
      const Vec2 shift(rng.uniform(-0.8, 0.8), gap);
      const Vec2 dir(std::cos(angle), std::sin(angle));
      for (std::size_t i = 0; i < 4; ++i)
        pair.b[i] = shift + length * (shape[i].x() * dir + shape[i].y() * perp(dir));
      if (rng.uniform() < 0.5) pair.b = reversed(pair.b);
      break;
    }
    case PairKind::kNearlyTouching: {
      pair.a = bowed_unit(rng, 0.15);
      const double gap =
          (rng.uniform() < 0.7 ? 1.0 : -1.0) * std::pow(10.0, rng.uniform(-6.0, -3.0));
      pair.b = tangent_partner(pair.a, rng.uniform(0.02, 0.98), gap, rng, rng.uniform() < 0.35);
      break;
    }
    case PairKind::kEndpoint: {
      pair.a = bowed_unit(rng, 0.15);
      const double gap = std::pow(10.0, rng.uniform(-3.0, -0.5));
      if (rng.uniform() < 0.5) {
        for (std::size_t i = 0; i < 4; ++i)
          pair.b[i] = Vec2(1.0 + gap + rng.uniform(0.0, 1.0), rng.uniform(-0.5, 0.5));
      } else {  // pointing away: a corner (end to end) minimum
        const Vec2 start(1.0 + gap, rng.uniform(-0.3, 0.3));
        const double angle = rng.uniform(-1.2, 1.2);
        pair.b = straight_polygon(
            start, start + rng.uniform(0.3, 1.0) * Vec2(std::cos(angle), std::sin(angle)));
        pair.b[1] += random_point(rng, 0.0, 0.05);
        if (rng.uniform() < 0.5) pair.b = reversed(pair.b);
      }
      if (rng.uniform() < 0.5) pair.a = reversed(pair.a);
      break;
    }
    case PairKind::kMultiCrossing: {
      const double h = rng.uniform(0.2, 1.0);
      pair.a = {Vec2(0.0, 0.0), Vec2(1.0 / 3.0, h), Vec2(2.0 / 3.0, -h), Vec2(1.0, 0.0)};
      for (Vec2& p : pair.a)
        p += random_point(rng, -0.02, 0.02);
      const double v = rng.uniform();
      if (v < 0.5) {
        pair.b =
            straight_polygon({-0.1, rng.uniform(-0.05, 0.05)}, {1.1, rng.uniform(-0.05, 0.05)});
      } else if (v < 0.8) {
        const double h2 = rng.uniform(0.2, 1.0);
        pair.b = {Vec2(-0.05, 0.0), Vec2(1.0 / 3.0, -h2), Vec2(2.0 / 3.0, h2), Vec2(1.05, 0.0)};
        for (Vec2& p : pair.b)
          p += random_point(rng, -0.02, 0.02);
      } else {  // a line grazing one hump of the S: touching there, far at the other
        const double peak = 0.2887 * h + rng.uniform(-1e-3, 1e-3);
        pair.b = straight_polygon({-0.1, peak}, {1.1, peak});
      }
      break;
    }
    case PairKind::kTypical:
      pair = typical_pair(rng);
      break;
    default:
      pair = degenerate_pair(rng);
      break;
  }
  return pair;
}

// A pair of the given kind, scaled by 1e-3..1e3, turned and moved by a few sizes.
inline std::pair<CubicSegment, CubicSegment> random_segment_pair(Rng& rng, PairKind kind) {
  const SegmentPair unit = unit_pair(rng, kind);
  const double scale = std::pow(10.0, rng.uniform(-3.0, 3.0));
  const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const Vec2 dir(std::cos(angle), std::sin(angle));
  const Vec2 offset = scale * random_point(rng, -3.0, 3.0);
  const auto place = [&](const BezierPolygon& p) {
    BezierPolygon out;
    for (std::size_t i = 0; i < 4; ++i)
      out[i] = offset + scale * (p[i].x() * dir + p[i].y() * perp(dir));
    return segment_from_bezier(out);
  };
  return {place(unit.a), place(unit.b)};
}

}  // namespace rugosim::testing
