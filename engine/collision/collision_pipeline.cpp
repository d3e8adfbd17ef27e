#include "engine/collision/collision_pipeline.h"

#include <algorithm>

namespace rugosim {
namespace {

// Below this many pairs a step's narrow phase is too short to be worth sharing out.
constexpr std::size_t kParallelPairs = 8;

}  // namespace

void CollisionPipeline::match_caches(const std::vector<BodyPair>& pairs) {
  // Both lists are sorted by (a, b): one merge, of indices only. The caches themselves are
  // moved by the thread that collides the pair (take_cache), so that this serial part stays
  // short and each cache is touched by one thread per call.
  const auto before = [](const BodyPair& p, const BodyPair& q) {
    return p.a < q.a || (p.a == q.a && p.b < q.b);
  };
  if (next_caches_.size() < pairs.size()) next_caches_.resize(pairs.size());
  cache_source_.resize(pairs.size());
  std::size_t old = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    while (old < cache_pairs_.size() && before(cache_pairs_[old], pairs[k]))
      ++old;
    cache_source_[k] = old < cache_pairs_.size() && cache_pairs_[old] == pairs[k] ? old : kNoCache;
  }
}

LeafPairCache& CollisionPipeline::take_cache(std::size_t k) {
  LeafPairCache& cache = next_caches_[k];
  if (cache_source_[k] != kNoCache) {
    std::swap(cache, caches_[cache_source_[k]]);
  } else {
    cache.a = 0;  // a new pair: nothing cached
  }
  return cache;
}

const std::vector<ContactManifold>& CollisionPipeline::detect(std::span<const PlacedShape> bodies,
                                                              ThreadPool* pool) {
  detect(bodies, pool, manifolds_);
  return manifolds_;
}

void CollisionPipeline::detect(std::span<const PlacedShape> bodies, ThreadPool* pool,
                               std::vector<ContactManifold>& out) {
  counts_ = {};
  proxies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    proxies_[i].box = bodies[i].shape->world_bounds(bodies[i].placement);
    proxies_[i].fixed = bodies[i].fixed;
    proxies_[i].asleep = bodies[i].asleep;
  }
  near_pairs_ = broad_phase_.find_pairs(proxies_);
  const std::vector<BodyPair>& pairs = near_pairs_;
  counts_.body_pairs = pairs.size();
  if (results_.size() < pairs.size()) results_.resize(pairs.size());
  const int threads = pool != nullptr && pairs.size() >= kParallelPairs ? pool->size() : 1;
  while (colliders_.size() < static_cast<std::size_t>(threads))
    colliders_.emplace_back(narrow_phase_);
  match_caches(pairs);

  const auto collide_pairs = [&](std::size_t begin, std::size_t end, int thread) {
    BodyPairCollider& collider = colliders_[static_cast<std::size_t>(thread)].collider;
    for (std::size_t k = begin; k < end; ++k) {
      const PlacedShape& a = bodies[pairs[k].a];
      const PlacedShape& b = bodies[pairs[k].b];
      PairResult& result = results_[k];
      // Wide enough that the pair's cache lasts a few steps of its relative motion.
      collider.collide(*a.shape, a.placement, *b.shape, b.placement, result.manifold,
                       &take_cache(k), 3.0 * (a.motion_per_step + b.motion_per_step));
      result.leaf_pairs = collider.last_leaf_pairs().size();
    }
  };
  try {
    if (threads > 1) {
      // Small chunks: the cost of a pair ranges from a box test to a long search.
      const std::size_t grain =
          std::max<std::size_t>(1, pairs.size() / (32 * static_cast<std::size_t>(threads)));
      pool->parallel_for(pairs.size(), grain, collide_pairs);
    } else {
      collide_pairs(0, pairs.size(), 0);
    }
  } catch (...) {
    // Some caches were moved and some not: forget them all, so that the next call starts
    // afresh (and alike whatever happened here).
    cache_pairs_.clear();
    throw;
  }

  std::swap(caches_, next_caches_);
  cache_pairs_ = pairs;

  std::size_t found = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    PairResult& result = results_[k];
    counts_.leaf_pairs += result.leaf_pairs;
    if (result.manifold.state() == PairState::kSeparated) continue;
    result.manifold.body_a = pairs[k].a;
    result.manifold.body_b = pairs[k].b;
    counts_.intersections += result.manifold.intersections.size();
    counts_.contacts += result.manifold.contacts.size();
    if (found == out.size()) out.emplace_back();
    // Swapped, not copied: the result takes the element's old storage, to be refilled by the
    // next call, so neither side allocates once a scene's contacts have been seen.
    std::swap(out[found++], result.manifold);
  }
  out.resize(found);
}

}  // namespace rugosim
