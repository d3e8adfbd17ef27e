#include "engine/geometry/curve_length.h"

#include <array>

namespace rugosim {
namespace {

// 8-point Gauss–Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290,
                                          0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873,
                                            0.2223810344533745, 0.1012285362903763};

}  // namespace

double curve_length(const PeriodicBSpline& curve) {
  double length = 0.0;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    const CubicSegment& segment = curve.segment(j);
    double sum = 0.0;
    for (std::size_t i = 0; i < kNodes.size(); ++i) {
      // Nodes ±x on [-1, 1] are (1 ± x) / 2 on [0, 1], and the interval halves the weights.
      sum += kWeights[i] * (segment.derivative(0.5 * (1.0 - kNodes[i])).norm() +
                            segment.derivative(0.5 * (1.0 + kNodes[i])).norm());
    }
    length += 0.5 * sum;
  }
  return length;
}

}  // namespace rugosim
