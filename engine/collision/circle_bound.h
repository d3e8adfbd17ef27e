// The curved certificate of the narrow phase (segment_distance.h): a lower bound of the distance
// between two cubic pieces from a circle that holds one piece inside and leaves the other
// outside.
//
// The slab bound (bezier_bounds.h) separates the pieces by a line, which is exact when both bend
// away from each other but fails when a convex piece rests in a concave one, as rough bodies in a
// pile do all the time: the concave piece bends towards the other on both sides of the nearest
// points, so no line through the gap clears it, and the search had to shrink its rectangles to
// where the bend is below the accuracy (about twenty halvings). A circle between the two
// curvatures clears both pieces at once and is as tight as the slab at the nearest points.
//
// With P(x) = ‖x − c‖² along a piece, the inner piece lies in the disk of radius √max P and the
// outer one outside that of radius √min P, so ‖a − b‖ ≥ √min P_outer − √max P_inner, for any
// centre c. P is a sextic, and its extremes over an interval are found exactly (at the ends or
// at roots of P', polynomial_range.h). With c on the line through the nearest points and a
// radius between the two pieces' curvatures, both extremes sit at the nearest points and the
// bound is the distance itself; where a piece strays past its circle farther out, the bound is
// lower, and the search halves the rectangle.
#pragma once

#include <limits>

#include "engine/geometry/cubic_segment.h"

namespace rugosim {

// A lower bound (m) of ‖a(s) − b(t)‖ over s in [s0, s1] and t in [t0, t1], from a circle centred
// on the line through a(s_ref) and b(t_ref) (points of the rectangle, normally a local minimum of
// the distance in it, where the bound is tight), through one of them, that holds that piece and
// leaves the other outside: its curvature is chosen from samples of both pieces over the
// rectangle (and their bends at the reference points), so that a piece whose curvature changes
// along it, or whose reference point is its end, still fits. −infinity when no such circle
// fits (both straight, or the convex one flatter than the concave one); the caller then falls
// back on other bounds or on smaller rectangles. Where a cheaper enclosure of the circle's
// distances (polynomial_range.h) already gives at least `needed` (m), that bound is returned;
// otherwise the exact extremes decide (always, by default).
double circle_separation_bound(const CubicSegment& a, const CubicSegment& b, double s_ref,
                               double t_ref, double s0, double s1, double t0, double t1,
                               double needed = std::numeric_limits<double>::infinity());

}  // namespace rugosim
