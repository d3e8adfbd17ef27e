#include "engine/dynamics/containment.h"

#include <algorithm>
#include <cstddef>

#include "engine/dynamics/overlap_depth.h"

namespace rugosim {
namespace {

constexpr int kSamplesPerSegment = 16;

}  // namespace

ContainmentSamples containment_samples(const RigidBody& body) {
  ContainmentSamples s;
  const PeriodicBSpline& curve = body.curve();
  const auto per_segment = static_cast<std::size_t>(kSamplesPerSegment);
  s.polygon.reserve(curve.size() * per_segment);
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (std::size_t k = 0; k < per_segment; ++k)
      s.polygon.push_back(curve.point(j, static_cast<double>(k) / kSamplesPerSegment));
  }
  double stray = 0.0;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (std::size_t k = 0; k < per_segment; ++k) {
      // The curve between two samples against the chord: its middle is the farthest, closely
      // enough for cubic pieces 1/16 of a segment long (doubled below).
      const Vec2 u = s.polygon[j * per_segment + k];
      const Vec2 v = s.polygon[(j * per_segment + k + 1) % s.polygon.size()];
      const Vec2 mid = curve.point(j, (static_cast<double>(k) + 0.5) / kSamplesPerSegment);
      stray = std::max(stray, (mid - 0.5 * (u + v)).norm());
    }
  }
  s.tolerance = 2.0 * stray + 1e-12 * body.bounding_radius();
  for (const Vec2& p : s.polygon)
    s.box.extend(p);
  return s;
}

std::optional<bool> lies_inside(const RigidBody& inner, const ContainmentSamples& inner_samples,
                                const RigidBody& outer, const ContainmentSamples& outer_samples) {
  // The inner samples in the outer body's frame; placing them adds roundings of the order of
  // the coordinates, covered by the tolerance's allowance for bodies far from the origin.
  const Transform2 to_outer = outer.placement().inverse() * inner.placement();
  const double slack = inner_samples.tolerance + outer_samples.tolerance;
  Aabb inner_box;
  for (const Vec2& corner : {inner_samples.box.min, inner_samples.box.max,
                             Vec2(inner_samples.box.min.x(), inner_samples.box.max.y()),
                             Vec2(inner_samples.box.max.x(), inner_samples.box.min.y())}) {
    inner_box.extend(to_outer.apply(corner));
  }
  const Aabb& outer_box = outer_samples.box;
  if (!(inner_box.min.x() >= outer_box.min.x() - slack &&
        inner_box.min.y() >= outer_box.min.y() - slack &&
        inner_box.max.x() <= outer_box.max.x() + slack &&
        inner_box.max.y() <= outer_box.max.y() + slack)) {
    return false;  // not even within the outer body's box
  }
  for (const Vec2& q : inner_samples.polygon) {
    const Vec2 p = to_outer.apply(q);
    if (distance_to_polygon(outer_samples.polygon, p) <= outer_samples.tolerance) continue;
    return inside_polygon(outer_samples.polygon, p);
  }
  return std::nullopt;
}

}  // namespace rugosim
