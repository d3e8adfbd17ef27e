// The alternative tolerance estimator of paper §2.2: the "universal threshold" of Donoho and
// Johnstone, computed from the finest wavelet details of a curve's multiresolution.
//
// The paper's formula is lambda = sigma * sqrt(2 ln m) / sqrt(m), with sigma the spread of the
// finest-level wavelet coefficients and m their number. Here:
// - The coefficients are the normal components of the m = n / 2 details of one analysis step
//   (multiresolution.h). Detail i lives at coarse parameter i + 1/2, so it is projected on the
//   normal of the coarse curve there; rugosity displaces the boundary across the curve, while
//   the tangential part also carries the uneven spacing of the control points, which is not
//   roughness. Where the coarse curve has no tangent (a cusp) the x component stands in: for
//   isotropic noise it has the same distribution.
// - sigma is estimated robustly as median(|x|) / 0.6745 (Donoho-Johnstone's median absolute
//   deviation): the few large coefficients that real features leave in the details (corners,
//   bumps) barely move a median, whereas they would inflate a standard deviation.
// - The details are not an orthonormal transform of the control points: displacing each fine
//   control point by independent N(0, s^2) noise gives details of standard deviation
//   s * kDetailNoiseGain. The estimate is divided by that gain, so sigma is in the units of the
//   control-point displacements, the same quantity as the sigma_j of lambda_j = q sigma_j.
#pragma once

#include <cstddef>
#include <span>

#include "engine/core/types.h"

namespace rugosim {

// Root of the sum of the squared weights of the detail filter
// d_i = (f_{2i-1} + f_{2i+3}) / 4 - (f_{2i} + f_{2i+2}) + 3/2 f_{2i+1}: sqrt(35 / 8).
inline constexpr double kDetailNoiseGain = 2.0916500663351889;

struct UniversalThreshold {
  double sigma = 0.0;                 // m: estimated std of the normal control-point noise
  double lambda = 0.0;                // m: sigma * sqrt(2 ln m) / sqrt(m)
  std::size_t coefficient_count = 0;  // m, the number of finest details
};

// Estimates sigma and lambda from a curve's control points. Throws std::invalid_argument
// unless the count is even and at least 8 (one wavelet level must exist).
UniversalThreshold estimate_universal_threshold(std::span<const Vec2> control_points);

}  // namespace rugosim
