// The length of a closed periodic cubic B-spline (its perimeter), by Gauss–Legendre quadrature
// of |c'(t)| over each segment. |c'| is the square root of a quartic, so no finite rule is
// exact; 8 points a segment give about 10 significant digits on the boundaries rugosim builds,
// far more than its one use needs (a body's thickness, rigid_body.h).
#pragma once

#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

double curve_length(const PeriodicBSpline& curve);  // m

// The length of one segment between parameters t0 ≤ t1 in [0, 1], by the same rule (m).
double segment_arc_length(const CubicSegment& segment, double t0, double t1);

}  // namespace rugosim
