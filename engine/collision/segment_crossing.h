// Do two cubic segments cross (paper §3.2, eq. 3: H(t_a, t_b) = a(t_a) − b(t_b) = 0)?
//
// A crossing is a root of H anywhere in [0, 1]², so this is the question "is the nearest
// distance zero?", and it is answered by the same search as nearest_points()
// (segment_distance.h): seeded Newton descent, whose steps near a root are Newton's method on
// H itself, a slab certificate, and a branch and bound over de Casteljau sub-polygons that
// stops at the first pair of points within crossing_distance(). Sharing the search is
// deliberate: the two answers can never disagree, which a separate Bézier-clipping root finder
// could not promise for pairs that come within rounding of touching.
//
// Touching at a single point and overlapping collinear pieces count here (distance 0); the
// collision layer then tells touching from crossing (touching.h): only a crossing deeper than
// the touching tolerance is backed off.
//
// Contract: find_crossing(a, b) has a value exactly when
// nearest_points(a, b).distance <= crossing_distance(a, b). A caller that needs both
// answers should call nearest_points() once and pass it to crossing_from().
#pragma once

#include <optional>

#include "engine/collision/segment_distance.h"
#include "engine/core/types.h"
#include "engine/geometry/cubic_segment.h"

namespace rugosim {

struct Crossing {
  double t_a = 0.0, t_b = 0.0;  // in [0, 1]
  Vec2 point = Vec2::Zero();    // m, midway between a(t_a) and b(t_b), which agree to the threshold
};

// A point where a and b (in the same frame) cross or touch, or nullopt if they are apart.
std::optional<Crossing> find_crossing(const CubicSegment& a, const CubicSegment& b,
                                      const NarrowPhaseSettings& settings = {});

// The crossing implied by nearest points already computed for the same a, b and settings.
std::optional<Crossing> crossing_from(const NearestPoints& nearest, const CubicSegment& a,
                                      const CubicSegment& b,
                                      const NarrowPhaseSettings& settings = {});

}  // namespace rugosim
