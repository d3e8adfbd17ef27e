// Conservative bounds for the segment-pair narrow phase (paper §3.2): the pieces that let a
// subdivision search over parameter rectangles prove that a rectangle cannot hold a nearer
// pair of points than one already found.
//
// Two bounds are used, both exact in exact arithmetic:
// - chord bound: a cubic Bézier piece lies inside the convex hull of its control polygon, so
//   every point of it is within the chord deviation δ (the farther inner control point's
//   distance from the chord b0-b3) of the chord. The distance between two pieces is then at
//   least the distance between their chords minus δ_a + δ_b. δ shrinks fourfold per halving,
//   and is zero for straight pieces, so the bound is exact there.
// - separating-axis bound: for any unit n, min over the pieces of n·(a(s) − b(t)) is
//   min n·a − max n·b, and each of those is the extreme of a scalar cubic, found exactly from
//   the roots of its derivative. With n along the nearest-point direction this is the slab
//   certificate that a local minimum is the global one.
#pragma once

#include <array>
#include <optional>
#include <utility>

#include "engine/core/types.h"
#include "engine/geometry/cubic_segment.h"

namespace rugosim {

using BezierPolygon = std::array<Vec2, 4>;

// The two halves of a cubic Bézier piece, by de Casteljau at t = 1/2.
std::pair<BezierPolygon, BezierPolygon> split_in_half(const BezierPolygon& p);

// Largest distance from the piece to its chord b0-b3 (see above), m.
double chord_deviation(const BezierPolygon& p);

// Nearest points of two straight segments p0-p1 and q0-q1 (either may have zero length).
// u and v are the fractions along each. Robust for parallel and collinear segments: when the
// segments do not cross, the nearest pair always has an end point of one of them, so it is the
// best of four point-to-segment projections and never divides by a near-zero determinant.
struct ChordPair {
  double u = 0.0;
  double v = 0.0;
  double distance = 0.0;  // m
};
ChordPair closest_on_chords(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1);

// For two nearly parallel chords the nearest pair is ill-conditioned and lands on an end, while
// the curves' own nearest points or crossings usually lie inside the stretch where the chords
// run side by side: this gives the middle of that stretch (u on p0-p1, v on q0-q1), or nothing
// when the projections of q0-q1 onto p0-p1 do not overlap it.
std::optional<ChordPair> middle_of_chord_overlap(const Vec2& p0, const Vec2& p1, const Vec2& q0,
                                                 const Vec2& q1);

// Smallest value of k0 + k1 x + k2 x² + k3 x³ over [lo, hi].
double cubic_minimum(const std::array<double, 4>& k, double lo, double hi);

// min over s in [s0, s1], t in [t0, t1] of n·(a(s) − b(t)), for any direction n: a lower
// bound of ‖a(s) − b(t)‖ over that rectangle when n is a unit vector.
double separating_axis_bound(const CubicSegment& a, const CubicSegment& b, const Vec2& n, double s0,
                             double s1, double t0, double t1);

}  // namespace rugosim
