// Wavelet multiresolution of a closed periodic cubic B-spline (paper §2.1): the control
// points C^0 are split recursively into coarser control points C^-1, ..., C^-L and the
// details D^-1, ..., D^-L that restore each finer level exactly.
//
// The transform is a lifting scheme on the control points. Fine point f_{2i} sits over coarse
// point c_i (as in subdivision.h: coarse segment j becomes fine segments 2j and 2j+1), indices
// wrap (mod m for c and d, mod 2m for f) and alpha = 23/49:
//   analysis   s_i = 2 f_{2i} - (f_{2i-1} + f_{2i+1}) / 2
//              d_i = f_{2i+1} - (s_i + s_{i+1}) / 2
//              c_i = s_i + alpha (d_{i-1} + d_i)
//   synthesis  the same three steps undone in reverse order.
// Each step is undone exactly, so reconstruction is exact up to rounding. With d = 0 the
// synthesis is cubic B-spline subdivision, so the coarse curve refines to the fine one plus a
// detail curve; the analysis low-pass filter is the local least-squares reverse-subdivision
// filter of Samavati and Bartels, (23/196, -23/49, 9/28, 52/49, 9/28, -23/49, 23/196), so each
// coarse curve is a smoothed fit of the finer one rather than a decimation of it.
//
// A level exists while the control count is even and the coarse count stays >= 4, the
// minimum of a periodic cubic B-spline.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/types.h"

namespace rugosim {

// One analysis step: m coarse control points and the m details that restore the 2m finer ones.
struct WaveletLevel {
  std::vector<Vec2> coarse;   // m, in the units of the input points
  std::vector<Vec2> details;  // m; details[i] lives at fine index 2i+1 (coarse parameter i+1/2)
};

// Splits 2m control points into m coarse points and m details. Throws std::invalid_argument
// unless the count is even and at least 8 (so that the coarse curve has >= 4 points).
WaveletLevel decompose(std::span<const Vec2> fine);

// The exact inverse of decompose: 2m control points from m coarse points and m details.
// Throws std::invalid_argument when the sizes differ or there are fewer than 4 coarse points.
std::vector<Vec2> reconstruct(std::span<const Vec2> coarse, std::span<const Vec2> details);

// How many times n control points can be halved while the count being halved is even and the
// result keeps >= 4 points: 4 -> 0, 6 -> 0, 8 -> 1, 12 -> 1, 24 -> 2, 1024 -> 8.
int max_wavelet_levels(std::size_t n);

// All levels of one curve, kept so that any level's control points are a reference away (the
// collision tree orients each of its levels by the matching coarse curve).
class Multiresolution {
 public:
  static constexpr int kAllLevels = -1;

  // Decomposes `finest` (level 0) into min(max_levels, max_wavelet_levels(n)) coarser levels,
  // or all possible with kAllLevels. Throws std::invalid_argument when fewer than 4 points are
  // given, one is not finite, or max_levels < -1.
  explicit Multiresolution(std::vector<Vec2> finest, int max_levels = kAllLevels);

  // Number of coarser levels L; levels run from 0 (finest, the input) to L (coarsest).
  int level_count() const { return static_cast<int>(details_.size()); }

  // Control points of a level in [0, L]: level k has n / 2^k points (C^-k of the paper).
  // Throws std::out_of_range outside [0, L].
  const std::vector<Vec2>& control_points(int level) const;

  // Details in [0, L): those that take level + 1 back to level (D^-(k+1) of the paper).
  // Throws std::out_of_range outside [0, L).
  const std::vector<Vec2>& details(int level) const;

  // The finest control points rebuilt from a level in [0, L] and the details below it; equal
  // to the input up to rounding. Throws std::out_of_range outside [0, L].
  std::vector<Vec2> reconstruct_finest(int from_level) const;

 private:
  std::vector<std::vector<Vec2>> levels_;   // L + 1 entries, finest first
  std::vector<std::vector<Vec2>> details_;  // L entries
};

}  // namespace rugosim
