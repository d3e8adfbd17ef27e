// The boundary as drawn: the smooth curve plus statistically generated rugosity detail (paper
// §2.2 and §5). The paper models the detail beyond the explicit control points as further
// control points displaced from the curve by independent normal noise of variance σ_j². We draw
// that model as a property of the body, not of the pixels: the curve is sampled at equal steps
// of arc length s, and each sample moves along the normal by
//     d(s) = roughness_scale · σ(s) · noise(s),
// σ(s) the continuous profile through the segments' σ_j and noise a multi-octave B-spline noise
// in arc length (boundary_noise.h) with variance 1/2: d has RMS σ/√2 × roughness_scale, the
// statistic of the paper's model. The noise's coarsest wavelength is the correlation length ℓ,
// in metres, so segments of equal σ look alike whatever their length, and the same body shows
// the same detail at every resolution: more pixels only sample it more finely. Only octaves
// under a pixel, which could not be seen, are left out (and leaving one out changes no
// other). The detail is display-only: the physics never sees it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

struct DetailSettings {
  double pixel_size = 0.0;  // m per pixel of the camera (> 0)
  double spacing_px = 1.5;  // px, the longest step between samples along the boundary
  // Octaves whose lattice is finer than this (px) are left out: their wavelengths, under 2 px,
  // could not be seen, and their samples would cost the rasteriser (a frame of figure12a at
  // 720p took 3.7 times as long with octaves down to 0.5 px; bench_render frame/shader).
  double min_cell_px = 1.0;
  // The samples are at most 1/samples_per_cell of the finest octave's lattice apart, so that
  // the drawn shape is the same at every pixel size and nothing aliases.
  double samples_per_cell = 2.0;
  std::size_t max_points = std::size_t{1} << 16;  // most points of one outline
  double roughness_scale = 1.0;     // display-only exaggeration of the detail's amplitude
  double correlation_length = 0.0;  // m, ℓ; 0: kCorrelationPerSigma × the largest σ
  int octaves = 12;                 // most octaves: ℓ down to ℓ/2048
  double hurst = 0.8;
  double clamp_sigmas = 3.0;  // the noise's lattice values are clamped at this many σ
};

// ℓ by default, in units of the body's largest σ: the detail's slopes are then the same on a
// pebble and a boulder.
inline constexpr double kCorrelationPerSigma = 4.0;

struct DetailOutline {
  std::vector<Vec2> points;          // m, the curve's frame: a closed polyline, counter-clockwise
  std::vector<double> param;         // the curve's parameter u in [0, n) at each point
  std::vector<double> arc_length;    // m, s at each point (0 at u = 0, along the curve's u)
  std::vector<double> displacement;  // m, d(s) along the outward normal at each point
  double length = 0.0;               // m, the smooth curve's perimeter
  double correlation_length = 0.0;   // m, the ℓ used (0 for a smooth body)
  int octaves = 0;                   // octaves drawn at this pixel size
};

// `sigma` has one σ_j (m, ≥ 0) per segment of `curve`. The same curve, σ, seed and settings
// give the same outline, bit for bit. Throws std::invalid_argument for a pixel size ≤ 0, a σ
// list of the wrong length, or a roughness scale or correlation length < 0.
DetailOutline make_detail_outline(const PeriodicBSpline& curve, std::span<const double> sigma,
                                  std::uint64_t seed, const DetailSettings& settings);

}  // namespace rugosim
