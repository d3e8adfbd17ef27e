// Collision between two placed bodies (paper §3.2): the trees give the leaf pairs whose boxes
// overlap, the narrow phase classifies each pair of segments as crossing, in tolerated contact
// (‖d‖ <= λ_a(t_a) + λ_b(t_b)) or separated, and the contacts are merged into one manifold.
// Pairs that touch (touching.h: within the narrow phase's accuracy, or reaching into each other
// by less than kTouchingDepthRelative of the smaller body's reach) are contacts at distance 0
// along the normal that clears them, not crossings.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/collision/aobb_tree.h"
#include "engine/collision/collision_shape.h"
#include "engine/collision/contact.h"
#include "engine/collision/segment_distance.h"
#include "engine/collision/touching.h"
#include "engine/core/transform.h"

namespace rugosim {

// What a body pair's last tree query found, kept between steps (as Box2D keeps its contacts from
// step to step): the leaf pairs whose boxes came within a margin of each other, and the relative
// placement they were found at. While the bodies have moved relative to each other by less than
// the margin, every leaf pair whose boxes overlap is among these, so testing these alone gives
// exactly what a new query would, in the same order, for a fraction of its cost.
struct LeafPairCache {
  // The margin, as a share of the smaller body's reach (AobbTree::reach): a resting body hops a
  // fraction of a millimetre per step, so a 10 cm rock keeps its candidates for many steps.
  static constexpr double kMarginRelative = 0.02;
  // ... and at most this share, however fast the pair moves: a margin as wide as the bodies
  // makes every leaf pair a candidate (256 × 256 segments for two fine circles), to be tested
  // at every detection, where a fresh query tests only the few leaves that meet (stress seed
  // 1160: 63 spinning mm bodies whose motion per step exceeded their size, 97% of the time in
  // the candidates' loop).
  static constexpr double kMarginRelativeMax = 0.1;

  // A candidate proved apart: farther than the widest band its segments can have by `margin`
  // when B was placed in A's frame by `b_to_a`. It stays apart while B moves relative to A by
  // less than the margin, and needs no narrow phase until then (the answer would again be
  // "separated").
  struct Apart {
    Transform2 b_to_a;
    double margin = 0.0;  // m; 0: no proof
  };

  std::uint64_t a = 0;  // the shapes it was made for (CollisionShape::id); 0: nothing cached
  std::uint64_t b = 0;
  Transform2 b_to_a;    // B's body frame in A's, when the candidates were found
  double margin = 0.0;  // m
  std::vector<LeafPair> candidates;
  std::vector<Apart> apart;  // per candidate
};

class BodyPairCollider {
 public:
  explicit BodyPairCollider(const NarrowPhaseSettings& settings = {}) : settings_(settings) {}

  // Fills `out` (cleared first, body indices left as they are) with what A and B, placed by
  // `place_a` and `place_b` (body frame -> world), have in common. Results are in world
  // coordinates. Reuses its buffers between calls: keep one collider per thread. With a cache
  // (one per body pair, kept by the caller between calls) the trees are queried again only when
  // the bodies have moved relative to each other by more than its margin; the result is the
  // same, bit for bit.
  // A new query of the cache uses a margin of at least `min_margin` (m).
  void collide(const CollisionShape& a, const Transform2& place_a, const CollisionShape& b,
               const Transform2& place_b, ContactManifold& out, LeafPairCache* cache = nullptr,
               double min_margin = 0.0);

  // Leaf pairs the last call examined (for statistics and tests).
  const std::vector<LeafPair>& last_leaf_pairs() const { return leaf_pairs_; }

 private:
  NarrowPhaseSettings settings_;
  // The leaf pairs whose boxes overlap, from the cache when it still holds (see above).
  void find_leaf_pairs(const CollisionShape& a, const CollisionShape& b, const Transform2& b_to_a,
                       LeafPairCache* cache, double min_margin);

  std::vector<LeafPair> leaf_pairs_;
  std::vector<LeafPairCache::Apart*> leaf_apart_;  // per leaf pair, its proof in the cache
  std::vector<Obb> b_leaf_boxes_;                  // B's leaf boxes in A's frame, made on use
  std::vector<std::uint8_t> b_leaf_placed_;        // per B segment: its box is in b_leaf_boxes_
  std::vector<Contact> candidates_;
};

// Merges contacts that describe the same place: nearest points of neighbouring leaf pairs
// (same or adjacent segments on both bodies) closer together than the combined tolerance band,
// as around a shared joint. Keeps the closest of each group; the order of the result is
// deterministic (by segment and parameter). (Minima at a segment's end that are not minima of
// the whole curves are dropped before, in collide().)
void merge_duplicate_contacts(std::vector<Contact>& contacts, std::size_t segments_a,
                              std::size_t segments_b);

}  // namespace rugosim
