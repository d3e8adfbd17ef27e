// Broad phase: which bodies are close enough to need the tree test. Sort-and-sweep over the
// world boxes of the bodies' root boxes, so N bodies cost about N log N plus the pairs found,
// not N² box tests. The order from the previous call is kept and re-sorted by insertion,
// which is nearly linear while bodies move coherently from frame to frame.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/aabb.h"

namespace rugosim {

struct BroadPhaseProxy {
  Aabb box;             // m, world: contains the body and its tolerance band
  bool fixed = false;   // never moves
  bool asleep = false;  // at rest until something touches it
};

struct BodyPair {
  std::uint32_t a = 0;  // a < b, indices into the proxies
  std::uint32_t b = 0;
  friend bool operator==(const BodyPair&, const BodyPair&) = default;
};

// A pair needs testing only if one of its bodies is moving: two fixed bodies never collide,
// and a sleeping body only needs to wake when an awake one reaches it.
inline bool proxy_moves(const BroadPhaseProxy& p) {
  return !p.fixed && !p.asleep;
}
inline bool pair_can_interact(const BroadPhaseProxy& a, const BroadPhaseProxy& b) {
  return proxy_moves(a) || proxy_moves(b);
}

class SweepAndPrune {
 public:
  // Every pair (a < b) whose boxes overlap (touching counts) and that can interact, sorted by
  // (a, b) so the result does not depend on the sort order.
  const std::vector<BodyPair>& find_pairs(std::span<const BroadPhaseProxy> proxies);

 private:
  std::vector<std::uint32_t> order_;  // proxies sorted by box.min along the sweep axis
  // A box in sweep order: its extent along the sweep axis and the other one.
  struct Swept {
    double lo = 0.0, hi = 0.0;
    double other_lo = 0.0, other_hi = 0.0;
    std::uint32_t index = 0;
    bool moves = false;  // proxy_moves
  };
  std::vector<Swept> swept_;
  std::vector<BodyPair> pairs_;
  std::vector<BodyPair> sorted_;       // scratch of the final sort
  std::vector<std::uint32_t> starts_;  // per body a: where its pairs begin in sorted_
  std::vector<std::uint32_t> cursor_;
  int axis_ = 0;  // 0 = x, 1 = y: the axis along which the boxes spread most
};

}  // namespace rugosim
