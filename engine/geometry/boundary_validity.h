// Whether a closed boundary is usable as a body: finite, enclosing an area, and simple (it
// neither crosses nor touches itself). A crossing curve has no inside, so its mass properties,
// tolerance bands and contact normals would mean nothing; scenes reject such bodies.
//
// Method. Each segment is flattened into k equal parameter steps, k chosen so that the chord
// error, at most max|f''|·(1/k)²/8 (f'' is linear, so its largest norm on the segment is at
// t = 0 or t = 1), stays below τ = kBoundaryRelativeTolerance × the hull diagonal; k is capped
// at kMaxPiecesPerSegment. The polyline's edges, in curve order, go into a binary tree of boxes
// that also keeps each run's cone of edge directions: a run whose directions span less than a
// half turn is monotone and cannot meet itself, nor can two neighbouring runs whose union is
// monotone, so only runs whose boxes overlap and that may turn are compared (O(m log m) on
// smooth curves). Edge pairs are tested with exact orientation predicates: touching, an
// endpoint on an edge and collinear overlap all count as crossing. Vertices at segment joints
// are computed once, so consecutive edges share bitwise-equal vertices; consecutive edges
// count as crossing only when they fold back onto each other.
//
// What the tolerance means: the polyline lies within τ of the curve. So a boundary whose
// parts come within about 2τ of each other (about 1e-6 of its size) may be treated as
// crossing even if it does not quite touch, and a true crossing can be missed only when both
// arcs stay within about 2τ of each other all through it (a tangential graze). Boundaries
// that near are not worth simulating either way.
#pragma once

#include <cstddef>
#include <string>

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

// Flattening tolerance as a fraction of the curve's hull diagonal.
inline constexpr double kBoundaryRelativeTolerance = 1e-6;
// Bounds the work on pathological segments (|f''| above about 8 hull diagonals); where it
// binds, that segment's chord error is max|f''|/(8 k²) rather than τ.
inline constexpr std::size_t kMaxPiecesPerSegment = 1024;

enum class BoundaryIssue {
  kNone,
  kNonFinite,     // a segment overflows, or coordinates pass 1e150 m (products would)
  kZeroArea,      // |area| ≤ kMinRelativeArea × hull diagonal²
  kSelfCrossing,  // two parts of the curve cross or touch (or one segment loops)
};

struct ValidityReport {
  bool valid = true;
  BoundaryIssue issue = BoundaryIssue::kNone;
  std::string reason;  // empty when valid, else e.g. "segments 3 and 11 cross near (0.52, 1.1)"
  // For kSelfCrossing: the two segments (segment_a ≤ segment_b; equal for a loop within one
  // segment) and the approximate crossing point, m. For kNonFinite: segment_a is the segment.
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  Vec2 where = Vec2::Zero();
};

// Checks, in order: finite coordinates; control points not all on one line; no crossing
// (reported before zero area, since a symmetric figure-eight also has zero signed area);
// |signed area| above kMinRelativeArea × hull diagonal². The first failure is reported.
ValidityReport check_boundary(const PeriodicBSpline& curve);

// The exact sign of cross(b − a, c − a): +1 when c lies left of the line a→b, −1 right, 0 on
// it. A floating-point filter decides most calls; the rest are summed exactly. Exact while
// products of coordinates neither overflow nor underflow (|coordinates| within 1e-140..1e140).
int orientation_sign(const Vec2& a, const Vec2& b, const Vec2& c);

}  // namespace rugosim
