// The boundary as drawn: the smooth curve plus statistically generated rugosity detail (paper
// §2.2 and §5). The paper models the detail beyond the explicit control points as further
// control points displaced from the curve by independent normal noise of variance σ_j². We
// refine the control polygon by uniform subdivision (the same curve), displace each finer
// control point along the normal by σ(u)·N(0, 1) from a seeded generator of our own (σ(u) the
// continuous profile through the segments' σ_j), and draw the resulting B-spline. The level is
// the finest whose control points are still at least `spacing_px` pixels apart: detail finer
// than a pixel cannot be seen and is not generated.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

struct DetailSettings {
  double pixel_size = 0.0;  // m per pixel of the camera (> 0)
  double spacing_px = 1.5;  // px, finest spacing of the displaced control points
  int max_level = 8;        // most subdivision levels
  std::size_t max_points = std::size_t{1} << 16;  // most points of one outline
  double clamp_sigmas = 3.0;  // noise is clamped at this many σ (no rare spikes)
};

struct DetailOutline {
  std::vector<Vec2> points;   // m, the curve's frame: a closed polyline, counter-clockwise
  std::vector<double> param;  // the coarse curve's parameter u in [0, n) at each point
  int level = 0;              // subdivision levels used
};

// `sigma` has one σ_j (m, ≥ 0) per segment of `curve`. The same curve, σ, seed and settings
// give the same outline, bit for bit. Throws std::invalid_argument for a pixel size ≤ 0 or a σ
// list of the wrong length.
DetailOutline make_detail_outline(const PeriodicBSpline& curve, std::span<const double> sigma,
                                  std::uint64_t seed, const DetailSettings& settings);

}  // namespace rugosim
