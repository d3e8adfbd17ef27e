// Nearest points of two cubic segments (paper §3.2, eq. 4), over the whole parameter square
// [0, 1]², edges and corners included: the global minimum of ‖a(t_a) − b(t_b)‖.
//
// Method (a local answer, then a proof that it is global, else a search that finds one):
// 1. Seed: the nearest points of the two chords b0-b3, taken as curve parameters. For the
//    nearly straight segments that make up most boundaries this lands in the right basin.
// 2. Newton descent on ‖a − b‖² with the bounds as an active set (segment_pair_newton.h), so
//    minima on edges and at corners are found, and maxima and saddles never are. Near a
//    crossing this is Newton's method on eq. 3.
// 3. Certificate: with n the unit vector from b(t_b) to a(t_a), every pair satisfies
//    ‖a(s) − b(t)‖ ≥ min_s n·a(s) − max_t n·b(t); both extremes are exact (roots of a quadratic).
//    If the bound reaches the local distance, less the accuracy, it is the global minimum.
//    This holds for separated pairs that curve away from each other or are straight (the
//    common case), at edge and corner minima too, and costs two quadratic solves. If it fails,
//    steps 2-3 are tried once more from the middle of the stretch where the chords run side
//    by side (nearly parallel pieces, where the chords' nearest points sit at an end).
// 4. Otherwise (several local minima, a concave piece facing a convex one or a point, loops),
//    a best-first branch and bound over parameter rectangles: each rectangle carries the
//    de Casteljau sub-polygons of both segments and the chord lower bound (bezier_bounds.h);
//    a rectangle is dropped when its bound cannot beat the best distance by more than the
//    accuracy, or when a short descent inside it passes the certificate of step 3 restricted
//    to it; otherwise it is halved along the parameter whose piece is further from straight
//    (or both). A new best is polished by a descent over the whole square. The best pair seen
//    is always a true pair of curve points, so the answer is an upper bound within the
//    accuracy of the true minimum.
//
// Cost (Release, this machine's benchmark, bench/narrow_phase_bench.cpp): about 0.25 us for a
// separated or touching pair of nearly straight segments and 0.4 us for a crossing one; a few
// microseconds (tens of rectangles) when the search runs, e.g. a concave piece facing a convex
// one, where no linear certificate can hold until the rectangles are tiny.
//
// Accuracy: the distance returned exceeds the true minimum by at most nearest_points_accuracy()
// (relative_accuracy, 1e-12 by default, of the larger segment plus a rounding allowance),
// unless the search runs out of depth or rectangles (a pathological pair, or settings made
// coarse on purpose; the best pair found is returned). A pair at most crossing_distance()
// apart is treated as touching, the search stops there, and find_crossing()
// (segment_crossing.h) reports exactly those pairs.
#pragma once

#include <limits>
#include <optional>

#include "engine/core/types.h"
#include "engine/geometry/cubic_segment.h"

namespace rugosim {

// The knobs of the search (the accuracy presets of engine/dynamics/accuracy.h set them). The
// defaults are those of the "normal" preset.
struct NarrowPhaseSettings {
  // Dimensionless: the certificate's slack, as a fraction of the larger segment's size.
  double relative_accuracy = 1e-12;
  // Newton steps of a descent from a seed (the chords' nearest points, or the middle of the
  // stretch where they run side by side): enough for the linear convergence of a tangential
  // touch, where f grows like the fourth power of the offset, the slowest case the certificate
  // can close.
  int seed_iterations = 40;
  // Halvings of the parameter intervals in the search for seeds: past 2^-48 a rectangle's
  // points agree to rounding. A rectangle at this depth is not split again: its point seeds a
  // full descent instead.
  int max_depth = 48;
  // Rectangles examined before giving up with the best pair found.
  int max_cells = 4096;
};

struct NearestPoints {
  double t_a = 0.0, t_b = 0.0;  // in [0, 1]
  Vec2 point_a = Vec2::Zero();  // m, a.point(t_a)
  Vec2 point_b = Vec2::Zero();  // m, b.point(t_b)
  double distance = 0.0;        // m, ‖point_a − point_b‖
};

// Globally nearest points of a and b, given in the same frame.
NearestPoints nearest_points(const CubicSegment& a, const CubicSegment& b,
                             const NarrowPhaseSettings& settings = {});

// What nearest_points_within found.
struct WithinThreshold {
  // nearest_points' own answer, bit for bit, unless the pair was proved farther apart than the
  // threshold.
  std::optional<NearestPoints> nearest;
  // m: a proved lower bound of the distance between the segments, or −infinity when none was
  // proved (a search that had to give its best pair without a certificate). Above the threshold
  // when `nearest` is empty; within twice the accuracy below the distance when the nearest
  // points were certified.
  double lower_bound = -std::numeric_limits<double>::infinity();
  // m: crossing_distance(a, b), which the search works out anyway (the caller needs it too).
  double crossing_distance = 0.0;
};

// The same, for a caller that needs the nearest points only of pairs that come within
// `threshold` (m) of each other (the collision layer: a pair farther apart than its tolerance
// band is simply separated): no nearest points once it has proved that every pair of points is
// farther apart than max(threshold, crossing_distance()) + nearest_points_accuracy(), which for a
// pair well apart takes a few bounds where pinning down the exact minimum can take a long
// search. It may also give them for a pair farther apart than the threshold, when they came
// cheaper than a proof. The lower bound lets a caller keep the answer while the segments move
// by less than its margin.
WithinThreshold nearest_points_within(const CubicSegment& a, const CubicSegment& b,
                                      double threshold, const NarrowPhaseSettings& settings = {});

// How far above the true minimum nearest_points() may be, m: relative_accuracy of the larger
// segment's hull diagonal plus 64 roundings of the largest coordinate sum (evaluations far
// from the origin cannot be more exact than that).
double nearest_points_accuracy(const CubicSegment& a, const CubicSegment& b,
                               const NarrowPhaseSettings& settings = {});

// Distances at or below this are "zero", m: 4x the accuracy, so that touching or crossing
// curves (true minimum 0) are always reported as such.
double crossing_distance(const CubicSegment& a, const CubicSegment& b,
                         const NarrowPhaseSettings& settings = {});

}  // namespace rugosim
