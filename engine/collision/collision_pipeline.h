// Collision detection for a whole world: the broad phase picks the body pairs whose boxes
// overlap, and each pair goes through the trees and the narrow phase (BodyPairCollider).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/collision/body_pair_collider.h"
#include "engine/collision/broad_phase.h"
#include "engine/collision/collision_shape.h"
#include "engine/collision/contact.h"
#include "engine/core/transform.h"

namespace rugosim {

struct PlacedShape {
  const CollisionShape* shape = nullptr;
  Transform2 placement;  // body frame -> world
  bool fixed = false;
  bool asleep = false;
};

struct CollisionCounts {
  std::size_t body_pairs = 0;     // pairs the broad phase passed on
  std::size_t leaf_pairs = 0;     // segment pairs the trees passed on to the narrow phase
  std::size_t intersections = 0;  // crossing segment pairs
  std::size_t contacts = 0;       // tolerated contacts after merging
};

class CollisionPipeline {
 public:
  explicit CollisionPipeline(const NarrowPhaseSettings& narrow_phase = {})
      : collider_(narrow_phase) {}

  // One manifold per body pair that crosses or touches within its bands, sorted by
  // (body_a, body_b) with body_a < body_b; body indices are positions in `bodies`.
  const std::vector<ContactManifold>& detect(std::span<const PlacedShape> bodies);

  const CollisionCounts& counts() const { return counts_; }
  // The broad-phase pairs of the last detect(): bodies whose boxes (band included) overlap,
  // touching or not; sorted by (a, b).
  const std::vector<BodyPair>& near_pairs() const { return near_pairs_; }

 private:
  SweepAndPrune broad_phase_;
  BodyPairCollider collider_;
  std::vector<BroadPhaseProxy> proxies_;
  std::vector<ContactManifold> manifolds_;
  std::vector<BodyPair> near_pairs_;
  ContactManifold scratch_;
  CollisionCounts counts_;
};

}  // namespace rugosim
