// What collision needs to know of one body, in its body frame, built once: the boundary curve,
// its tolerances along the boundary, and its augmented OBB tree (paper §3.1). Nothing here
// changes while the body moves; placement comes with each query as a Transform2.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/collision/aobb_tree.h"
#include "engine/core/aabb.h"
#include "engine/core/transform.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/tolerance_profile.h"

namespace rugosim {

// Smallest contact band a body brings, relative to its size: with σ = 0 (no band at all) two
// bodies could only ever cross or be apart, and a step could never end in contact.
inline constexpr double kMinContactBandRelative = 1e-6;

class CollisionShape {
 public:
  // Throws std::invalid_argument when the profile's size differs from the segment count or the
  // curve runs clockwise (orientation.h's make_counter_clockwise normalises it first).
  CollisionShape(PeriodicBSpline curve, ToleranceProfile tolerances);

  const PeriodicBSpline& curve() const { return curve_; }
  const ToleranceProfile& tolerances() const { return tolerances_; }
  const AobbTree& tree() const { return tree_; }
  // m: kMinContactBandRelative times the curve's size. A pair is in contact when its distance
  // is within max(λ_a(t_a) + λ_b(t_b), min_band_a + min_band_b); the leaf boxes hold it too.
  double min_band() const { return min_band_; }
  // m: the largest tolerance λ_j(t) over segment j (ToleranceProfile::segment_range), at least
  // min_band(): no contact on segment j can have a wider share of the band.
  double segment_band(std::size_t j) const { return segment_band_[j]; }
  // m: the least tolerance λ(t) anywhere on the boundary, at least min_band(): no contact of
  // this body has a narrower share of the band.
  double least_band() const { return least_band_; }

  // World box around the placed body and its tolerance band, for the broad phase.
  Aabb world_bounds(const Transform2& placement) const;

  // A number no other shape built in this process has (copies keep it: the same geometry), for
  // caches that must tell shapes apart even where one was freed and another built at its address.
  std::uint64_t id() const { return id_; }

 private:
  PeriodicBSpline curve_;
  ToleranceProfile tolerances_;
  double min_band_ = 0.0;
  double least_band_ = 0.0;
  std::vector<double> segment_band_;  // m, per segment
  std::uint64_t id_ = 0;
  AobbTree tree_;
};

}  // namespace rugosim
