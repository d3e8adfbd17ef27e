#include "engine/dynamics/overlap_depth.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rugosim {

std::vector<Vec2> sampled_boundary(const RigidBody& body, int samples_per_segment) {
  std::vector<Vec2> points;
  const PeriodicBSpline& curve = body.curve();
  points.reserve(curve.size() * static_cast<std::size_t>(samples_per_segment));
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (int k = 0; k < samples_per_segment; ++k) {
      const double t = static_cast<double>(k) / samples_per_segment;
      points.push_back(body.world_point(curve.point(j, t)));
    }
  }
  return points;
}

bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  // Winding number by upward and downward crossings of the ray from p towards +x.
  int winding = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& u = polygon[i];
    const Vec2& v = polygon[(i + 1) % n];
    const double side = (v.x() - u.x()) * (p.y() - u.y()) - (p.x() - u.x()) * (v.y() - u.y());
    if (u.y() <= p.y()) {
      if (v.y() > p.y() && side > 0.0) ++winding;
    } else if (v.y() <= p.y() && side < 0.0) {
      --winding;
    }
  }
  return winding != 0;
}

double distance_to_polygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& u = polygon[i];
    const Vec2 e = polygon[(i + 1) % n] - u;
    const double len2 = e.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - u).dot(e) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (u + s * e - p).norm());
  }
  return best;
}

namespace {

double reach_into(const std::vector<Vec2>& samples, const std::vector<Vec2>& polygon) {
  double depth = 0.0;
  for (const Vec2& p : samples) {
    if (inside_polygon(polygon, p)) depth = std::max(depth, distance_to_polygon(polygon, p));
  }
  return depth;
}

}  // namespace

double sampled_overlap_depth(const RigidBody& a, const RigidBody& b, int samples_per_segment) {
  const std::vector<Vec2> pa = sampled_boundary(a, samples_per_segment);
  const std::vector<Vec2> pb = sampled_boundary(b, samples_per_segment);
  return std::max(reach_into(pa, pb), reach_into(pb, pa));
}

}  // namespace rugosim
