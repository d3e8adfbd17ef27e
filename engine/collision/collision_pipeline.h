// Collision detection for a whole world: the broad phase picks the body pairs whose boxes
// overlap, and each pair goes through the trees and the narrow phase (BodyPairCollider).
//
// The pairs are independent, so with a thread pool they are shared among its threads, each
// with a collider of its own; each pair's result goes to its own slot and the slots are read in
// pair order, so the manifolds are the same, bit for bit, whatever the number of threads.
//
// Each pair keeps what its tree query found from call to call (LeafPairCache), as long as the
// broad phase keeps finding it: in a pile, where bodies barely move between steps, the trees
// are queried again only now and then.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/collision/body_pair_collider.h"
#include "engine/collision/broad_phase.h"
#include "engine/collision/collision_shape.h"
#include "engine/collision/contact.h"
#include "engine/core/thread_pool.h"
#include "engine/core/transform.h"

namespace rugosim {

struct PlacedShape {
  const CollisionShape* shape = nullptr;
  Transform2 placement;  // body frame -> world
  bool fixed = false;
  bool asleep = false;
  // m: how far the body can move in a step, a hint for how wide a margin the pair caches keep
  // (a fast body would otherwise outrun its cache every step); 0 when unknown or still.
  double motion_per_step = 0.0;
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
      : narrow_phase_(narrow_phase) {}

  // One manifold per body pair that crosses or touches within its bands, sorted by
  // (body_a, body_b) with body_a < body_b; body indices are positions in `bodies`. The pairs
  // are shared among the threads of `pool` when one is given.
  const std::vector<ContactManifold>& detect(std::span<const PlacedShape> bodies,
                                             ThreadPool* pool = nullptr);
  // The same manifolds written into `out` (its elements' storage reused: no allocation once a
  // scene's contacts have been seen).
  void detect(std::span<const PlacedShape> bodies, ThreadPool* pool,
              std::vector<ContactManifold>& out);

  const CollisionCounts& counts() const { return counts_; }
  // The broad-phase pairs of the last detect(): bodies whose boxes (band included) overlap,
  // touching or not; sorted by (a, b).
  const std::vector<BodyPair>& near_pairs() const { return near_pairs_; }

 private:
  // Finds, for each of `pairs` (sorted by (a, b)), the index of its cache among the last
  // call's pairs (cache_source_).
  void match_caches(const std::vector<BodyPair>& pairs);
  // Pair k's cache, moved to its place in next_caches_ (by the thread colliding the pair).
  LeafPairCache& take_cache(std::size_t k);

  // What the narrow phase found for one broad-phase pair.
  struct PairResult {
    ContactManifold manifold;
    std::size_t leaf_pairs = 0;
  };

  NarrowPhaseSettings narrow_phase_;
  SweepAndPrune broad_phase_;
  // One collider per thread (they keep scratch buffers), each on cache lines of its own: the
  // ends of its buffers change at every push_back, and two threads' colliders side by side
  // could share a line (false sharing). Measured alone the gain was within noise; it costs
  // nothing.
  struct alignas(64) ThreadCollider {
    explicit ThreadCollider(const NarrowPhaseSettings& settings) : collider(settings) {}
    BodyPairCollider collider;
  };
  std::vector<ThreadCollider> colliders_;
  std::vector<BroadPhaseProxy> proxies_;
  std::vector<ContactManifold> manifolds_;
  std::vector<BodyPair> near_pairs_;
  std::vector<PairResult> results_;  // per pair of near_pairs_, reused between calls
  // Leaf-pair caches (body_pair_collider.h) of the pairs of the last call, in their order; a
  // pair that is still near takes its cache over to the next call.
  std::vector<LeafPairCache> caches_;
  std::vector<LeafPairCache> next_caches_;
  std::vector<BodyPair> cache_pairs_;
  static constexpr std::size_t kNoCache = static_cast<std::size_t>(-1);
  std::vector<std::size_t> cache_source_;  // per pair of this call: its index in caches_
  CollisionCounts counts_;
};

}  // namespace rugosim
