#include "engine/collision/touching.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/transform.h"

namespace rugosim {

Vec2 outward_normal(const CubicSegment& segment, double t) {
  const auto& a = segment.power();
  const double scale = a[1].norm() + a[2].norm() + a[3].norm();
  const double negligible = 1e-12 * scale;
  Vec2 direction = segment.derivative(t);
  if (direction.norm() <= negligible) {
    // f'(t0) = 0: just after t0 the curve moves along f''(t0), just before along −f''(t0).
    direction = t < 0.5 ? segment.second_derivative(t) : Vec2(-segment.second_derivative(t));
    if (direction.norm() <= negligible) direction = segment.third_derivative();
  }
  const double length = direction.norm();
  if (!(length > negligible) || !(length > 0.0)) return Vec2::Zero();
  // Counter-clockwise travel: the outside is on the right.
  return Vec2(direction.y(), -direction.x()) / length;
}

bool seen_from_inside(const NearestPoints& near, const CubicSegment& a, const CubicSegment& b) {
  const Vec2 d = near.point_a - near.point_b;
  const double half = 0.5 * d.norm();
  return d.dot(outward_normal(b, near.t_b)) < -half || d.dot(outward_normal(a, near.t_a)) > half;
}

namespace {

// Whether `point` of `segment` at t, the segment's nearest point to `other`, is a smooth
// interior point at which d = other − point runs against the outward normal (the first-order
// condition of a minimum makes it parallel there, up to the search's accuracy).
bool runs_inward(const CubicSegment& segment, double t, const Vec2& d) {
  constexpr double kEndShare = 1e-6;   // a nearest point this close to an end is the end
  constexpr double kParallel = 0.999;  // cos of the angle a first-order minimum leaves
  constexpr double kSmooth = 1e-3;     // speed, relative to the segment's, of a sharp corner
  if (!(t > kEndShare && t < 1.0 - kEndShare)) return false;
  const auto& p = segment.power();
  const double scale = p[1].norm() + p[2].norm() + p[3].norm();
  if (!(segment.derivative(t).norm() > kSmooth * scale)) return false;
  return d.dot(outward_normal(segment, t)) < -kParallel * d.norm();
}

}  // namespace

bool dipped_inside(const NearestPoints& near, const CubicSegment& a, const CubicSegment& b) {
  const Vec2 d = near.point_a - near.point_b;
  if (!(d.norm() > 0.0)) return false;
  return runs_inward(b, near.t_b, d) || runs_inward(a, near.t_a, Vec2(-d));
}

std::optional<Touch> touching(const NearestPoints& near, const CubicSegment& a,
                              const CubicSegment& b, double depth_tolerance,
                              const NarrowPhaseSettings& settings) {
  const double zero = crossing_distance(a, b, settings);
  const double shift = std::max(depth_tolerance, zero) + zero;
  const std::array<Vec2, 2> candidates = {outward_normal(b, near.t_b),
                                          Vec2(-outward_normal(a, near.t_a))};
  std::optional<Touch> best;
  double best_clearance = zero;  // a candidate must clear more than this
  for (const Vec2& n : candidates) {
    if (!(n.norm() > 0.5)) continue;  // no normal there (a segment shrunk to a point)
    const CubicSegment moved = a.transformed(Transform2(0.0, shift * n));
    const NearestPoints after = nearest_points(moved, b, settings);
    if (after.distance > best_clearance && !seen_from_inside(after, moved, b)) {
      best_clearance = after.distance;
      best = Touch{n, after.t_a, after.t_b};
    }
  }
  return best;
}

}  // namespace rugosim
