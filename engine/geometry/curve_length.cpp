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

double segment_arc_length(const CubicSegment& segment, double t0, double t1) {
  const double mid = 0.5 * (t0 + t1);
  const double half = 0.5 * (t1 - t0);
  double sum = 0.0;
  for (std::size_t i = 0; i < kNodes.size(); ++i) {
    // Nodes ±x on [-1, 1] are mid ± half·x on [t0, t1], and the interval scales the weights.
    sum += kWeights[i] * (segment.derivative(mid - half * kNodes[i]).norm() +
                          segment.derivative(mid + half * kNodes[i]).norm());
  }
  return half * sum;
}

double curve_length(const PeriodicBSpline& curve) {
  double length = 0.0;
  for (std::size_t j = 0; j < curve.size(); ++j)
    length += segment_arc_length(curve.segment(j), 0.0, 1.0);
  return length;
}

}  // namespace rugosim
