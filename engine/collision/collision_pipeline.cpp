#include "engine/collision/collision_pipeline.h"

namespace rugosim {

const std::vector<ContactManifold>& CollisionPipeline::detect(std::span<const PlacedShape> bodies) {
  counts_ = {};
  manifolds_.clear();
  proxies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    proxies_[i].box = bodies[i].shape->world_bounds(bodies[i].placement);
    proxies_[i].fixed = bodies[i].fixed;
    proxies_[i].asleep = bodies[i].asleep;
  }
  near_pairs_ = broad_phase_.find_pairs(proxies_);
  const std::vector<BodyPair>& pairs = near_pairs_;
  counts_.body_pairs = pairs.size();
  for (const BodyPair& pair : pairs) {
    const PlacedShape& a = bodies[pair.a];
    const PlacedShape& b = bodies[pair.b];
    collider_.collide(*a.shape, a.placement, *b.shape, b.placement, scratch_);
    counts_.leaf_pairs += collider_.last_leaf_pairs().size();
    if (scratch_.state() == PairState::kSeparated) continue;
    scratch_.body_a = pair.a;
    scratch_.body_b = pair.b;
    counts_.intersections += scratch_.intersections.size();
    counts_.contacts += scratch_.contacts.size();
    manifolds_.push_back(scratch_);
  }
  return manifolds_;
}

}  // namespace rugosim
