#include "engine/geometry/universal_threshold.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/geometry/multiresolution.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {
namespace {

// median(|x|) of N(0, 1): the 0.75 quantile of the standard normal.
constexpr double kNormalMedianAbs = 0.6745;

// Median of the values (reorders them); the mean of the two middle ones for an even count.
double median(std::vector<double>& values) {
  const std::size_t half = values.size() / 2;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(half);
  std::nth_element(values.begin(), middle, values.end());
  const double upper = *middle;
  if (values.size() % 2 != 0) return upper;
  const double lower = *std::max_element(values.begin(), middle);
  return 0.5 * (lower + upper);
}

}  // namespace

UniversalThreshold estimate_universal_threshold(std::span<const Vec2> control_points) {
  const std::size_t n = control_points.size();
  if (n % 2 != 0 || n < 8) {
    throw std::invalid_argument(
        "the universal threshold needs an even number of at least 8 control points, got " +
        std::to_string(n));
  }
  const WaveletLevel level = decompose(control_points);
  const std::size_t m = level.details.size();
  std::vector<double> magnitudes(m);
  for (std::size_t i = 0; i < m; ++i) {
    // Coarse parameter i + 1/2 is the middle of coarse segment i.
    const Vec2 tangent = make_segment(level.coarse, i).derivative(0.5);
    const double length = tangent.norm();
    const Vec2 normal = length > 0.0 ? Vec2(perp(tangent) / length) : Vec2(1.0, 0.0);
    magnitudes[i] = std::abs(level.details[i].dot(normal));
  }
  UniversalThreshold result;
  result.coefficient_count = m;
  result.sigma = median(magnitudes) / kNormalMedianAbs / kDetailNoiseGain;
  const double count = static_cast<double>(m);
  result.lambda = result.sigma * std::sqrt(2.0 * std::log(count)) / std::sqrt(count);
  return result;
}

}  // namespace rugosim
