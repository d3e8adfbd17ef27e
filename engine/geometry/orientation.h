// Orientation of a closed boundary. Bodies are normalised to run counter-clockwise (positive
// signed area, the inside on the left of the tangent), so a clockwise control polygon is
// reversed, and data kept per segment (such as the roughness σ_j of paper §2.2) must follow
// the segments to where they went.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

// A reordering of control points and where each new segment came from.
struct Reversal {
  std::vector<Vec2> control_points;         // m
  std::vector<std::size_t> old_segment_of;  // old_segment_of[k]: input segment under new segment k
  // When true, new segment k at t is the input's segment old_segment_of[k] at 1 − t;
  // when false, the control points and segments are unchanged (old_segment_of[k] = k).
  bool reversed = false;
};

// The same curve traversed the other way: r_k = c_{(1 − k) mod n}. New segment k uses
// r_{k−1..k+2} = c_{2−k}, c_{1−k}, c_{−k}, c_{−1−k}, the control points of old segment −k in
// reverse order, and the uniform basis is symmetric (B_i(t) = B_{3−i}(1 − t)), so new segment
// k at t is old segment (n − k) mod n at 1 − t.
Reversal reverse_orientation(std::span<const Vec2> control_points);

// Whether the curve runs counter-clockwise (its signed area is positive).
bool is_counter_clockwise(const PeriodicBSpline& curve);

// The control points of a counter-clockwise curve: reversed when the signed area of the
// curve is negative, unchanged otherwise (a zero-area curve is left as it is). Throws like
// the PeriodicBSpline constructor on fewer than 4 or non-finite points.
Reversal make_counter_clockwise(std::span<const Vec2> control_points);

// Per-segment data of the input, reordered to follow the segments of `reversal`.
template <typename T>
std::vector<T> follow_segments(const Reversal& reversal, std::span<const T> per_old_segment) {
  std::vector<T> result;
  result.reserve(reversal.old_segment_of.size());
  for (std::size_t old : reversal.old_segment_of)
    result.push_back(per_old_segment[old]);
  return result;
}

}  // namespace rugosim
