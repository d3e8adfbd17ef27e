// Touching or crossing? Two segments whose nearest points are within crossing_distance() of each
// other (segment_crossing.h) either cross — one curve runs into the other's body — or merely
// touch: a crate placed on a floor at exactly its resting height, faces closer than the preset's
// accuracy resolves, a corner resting on a face. Touching is a contact at distance zero, inside
// both bands (issue 15); only a crossing must be backed off.
//
// The test is a translation: move A away from B, along a candidate normal, by the depth
// tolerance plus crossing_distance(). If the moved pair is then farther apart than
// crossing_distance(), A reached into B by less than the tolerance along that normal: touching.
// A transversal crossing, or a corner driven into a face deeper than the tolerance, still
// crosses after any such move. The candidates are B's outward normal at its nearest point and
// the reverse of A's (one of them is a face's normal where a corner meets a face); the one that
// separates the pair most is the contact's normal.
#pragma once

#include <optional>

#include "engine/collision/segment_distance.h"
#include "engine/core/types.h"
#include "engine/geometry/cubic_segment.h"

namespace rugosim {

// Dimensionless: bodies reaching into each other by at most this share of the smaller body's
// size touch (issue 15: a scene summed in floating point places faces up to a few roundings
// across each other; 1e-9 of a 1 m body is a nanometre, far below any pixel or band).
inline constexpr double kTouchingDepthRelative = 1e-9;

// Unit normal of `segment` at parameter t, pointing out of its body (curves run
// counter-clockwise). Where the tangent vanishes (a sharp corner made of repeated control
// points) the first non-zero higher derivative gives the direction of travel instead.
Vec2 outward_normal(const CubicSegment& segment, double t);

// Whether nearest points `near` of a and b (one frame) show A on the inside of B: the vector d
// from B's point to A's runs into B (against B's outward normal) or out of A's far side (along
// A's outward normal), by more than half its length. Apart or touching from outside, d leaves B
// along its normal; where a curve turns a sharp corner its normal is one of the corner's edges',
// which d crosses at a right angle or better, never against.
bool seen_from_inside(const NearestPoints& near, const CubicSegment& a, const CubicSegment& b);

// Dimensionless: dipped_inside is trusted down to this share of the smaller body's size. A point
// on a curve's inner side lies inside the body only where the body is thicker than the depth: a
// plank thinner than the band has the far face of a body resting on it on its own inner side.
// Crossings that dip deeper than this are found by the seeds as crossings of their own.
inline constexpr double kDippedDepthRelative = 1e-6;

// Whether nearest points `near` of a and b (one frame) lie on the inner side of a curve, as a
// first-order minimum can say it for certain: at a smooth interior point of B (or of A) the
// vector d from B's point to A's is parallel to that curve's normal, and when it runs against
// B's outward normal (or along A's), A's point lies inside B (or B's inside A), |d| deep. That
// is a crossing whatever |d| is: the curves cross somewhere around it, closer to parallel than
// the narrow phase's seeds resolve (issue 15, stress seed 1076: a rock 2e-8 m inside a box's
// face, read as a contact whose normal pointed into the box). Points at a segment's end or at
// a sharp corner, where d need not be parallel to any normal, never count.
bool dipped_inside(const NearestPoints& near, const CubicSegment& a, const CubicSegment& b);

// How two curves touch: the contact's normal and where they reach deepest into each other.
struct Touch {
  Vec2 normal = Vec2::UnitY();  // unit, from B towards A
  // The nearest points of the pair once A is moved clear along `normal`: the deepest place of
  // the overlap (or of the touch), where the contact acts. The nearest points of the touching
  // pair itself may sit at an edge of a tiny overlap, where a fast slide or spin would still
  // drive the deeper middle in.
  double t_a = 0.0, t_b = 0.0;
};

// For a pair whose nearest points `near` (of a and b, in one frame) are within
// crossing_distance(), or within the depth tolerance and seen_from_inside(): the touch, if A
// moved by `depth_tolerance` (m; at least crossing_distance() is used) plus crossing_distance()
// along a candidate normal is clear of B (farther than crossing_distance() and not
// seen_from_inside); or nullopt when no candidate clears it (a crossing deeper than the
// tolerance). Of two candidates that clear it, the one that clears it more.
std::optional<Touch> touching(const NearestPoints& near, const CubicSegment& a,
                              const CubicSegment& b, double depth_tolerance,
                              const NarrowPhaseSettings& settings = {});

}  // namespace rugosim
