#include "engine/collision/collision_shape.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/geometry/orientation.h"

namespace rugosim {

namespace {
ToleranceProfile checked(const PeriodicBSpline& curve, ToleranceProfile tolerances) {
  if (tolerances.size() != curve.size()) {
    throw std::invalid_argument("the tolerance profile has " + std::to_string(tolerances.size()) +
                                " segments but the curve has " + std::to_string(curve.size()));
  }
  // Outward normals (contacts point from B to A) rely on counter-clockwise travel.
  if (!is_counter_clockwise(curve)) {
    throw std::invalid_argument("a collision shape's curve must run counter-clockwise");
  }
  return tolerances;
}
}  // namespace

CollisionShape::CollisionShape(PeriodicBSpline curve, ToleranceProfile tolerances)
    : curve_(std::move(curve)),
      tolerances_(checked(curve_, std::move(tolerances))),
      min_band_(kMinContactBandRelative * curve_.hull_bounds().diagonal()),
      tree_(curve_, tolerances_, min_band_) {
  static std::atomic<std::uint64_t> next_id{1};
  id_ = next_id.fetch_add(1, std::memory_order_relaxed);
  // A few roundings wider than the exact largest λ_j(t): ToleranceProfile::at evaluates the same
  // cubic another way, and a band must never exceed this bound, even by an ulp.
  segment_band_.reserve(curve_.size());
  least_band_ = std::max(tolerances_.range().lo, min_band_);
  for (std::size_t j = 0; j < curve_.size(); ++j) {
    segment_band_.push_back(std::max(tolerances_.segment_range(j).hi, min_band_) *
                            (1.0 + 16.0 * std::numeric_limits<double>::epsilon()));
  }
}

Aabb CollisionShape::world_bounds(const Transform2& placement) const {
  Aabb box;
  for (const Vec2& corner : tree_.root().box.transformed(placement).corners())
    box.extend(corner);
  return box;
}

}  // namespace rugosim
