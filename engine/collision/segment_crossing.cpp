// Paper §3.2, eq. 3: whether two segments cross, as the zero case of eq. 4's search.
#include "engine/collision/segment_crossing.h"

namespace rugosim {

std::optional<Crossing> crossing_from(const NearestPoints& nearest, const CubicSegment& a,
                                      const CubicSegment& b, const NarrowPhaseSettings& settings) {
  if (!(nearest.distance <= crossing_distance(a, b, settings))) return std::nullopt;
  return Crossing{nearest.t_a, nearest.t_b, 0.5 * (nearest.point_a + nearest.point_b)};
}

std::optional<Crossing> find_crossing(const CubicSegment& a, const CubicSegment& b,
                                      const NarrowPhaseSettings& settings) {
  return crossing_from(nearest_points(a, b, settings), a, b, settings);
}

}  // namespace rugosim
