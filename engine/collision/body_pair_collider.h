// Collision between two placed bodies (paper §3.2): the trees give the leaf pairs whose boxes
// overlap, the narrow phase classifies each pair of segments as crossing, in tolerated contact
// (‖d‖ <= λ_a(t_a) + λ_b(t_b)) or separated, and the contacts are merged into one manifold.
#pragma once

#include <vector>

#include "engine/collision/aobb_tree.h"
#include "engine/collision/collision_shape.h"
#include "engine/collision/contact.h"
#include "engine/collision/segment_distance.h"
#include "engine/core/transform.h"

namespace rugosim {

class BodyPairCollider {
 public:
  explicit BodyPairCollider(const NarrowPhaseSettings& settings = {}) : settings_(settings) {}

  // Fills `out` (cleared first, body indices left as they are) with what A and B, placed by
  // `place_a` and `place_b` (body frame -> world), have in common. Results are in world
  // coordinates. Reuses its buffers between calls: keep one collider per thread.
  void collide(const CollisionShape& a, const Transform2& place_a, const CollisionShape& b,
               const Transform2& place_b, ContactManifold& out);

  // Leaf pairs the last call examined (for statistics and tests).
  const std::vector<LeafPair>& last_leaf_pairs() const { return leaf_pairs_; }

 private:
  NarrowPhaseSettings settings_;
  std::vector<LeafPair> leaf_pairs_;
  std::vector<Contact> candidates_;
};

// Unit normal of curve B at parameter t of segment j, pointing out of B (B runs
// counter-clockwise). Where the tangent vanishes (a sharp corner made of repeated control
// points) the first non-zero higher derivative gives the direction of travel instead.
Vec2 outward_normal(const CubicSegment& segment, double t);

// Merges contacts that describe the same place: nearest points of neighbouring leaf pairs
// (same or adjacent segments on both bodies) closer together than the combined tolerance band,
// as around a shared joint. Keeps the closest of each group; the order of the result is
// deterministic (by segment and parameter). (Minima at a segment's end that are not minima of
// the whole curves are dropped before, in collide().)
void merge_duplicate_contacts(std::vector<Contact>& contacts, std::size_t segments_a,
                              std::size_t segments_b);

}  // namespace rugosim
