// Uniform subdivision of a periodic cubic B-spline (Lane-Riesenfeld): one level doubles the
// control points and describes exactly the same curve. Segment j of the coarse curve becomes
// segments 2j (t in [0, 1/2)) and 2j+1 (t in [1/2, 1)) of the fine one.
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

// One level: fine[2i] = (c[i-1] + 6 c[i] + c[i+1]) / 8, fine[2i+1] = (c[i] + c[i+1]) / 2.
std::vector<Vec2> subdivide_control_points(std::span<const Vec2> coarse);

// `levels` levels of subdivision (0 returns a copy).
PeriodicBSpline subdivide(const PeriodicBSpline& curve, int levels = 1);

}  // namespace rugosim
