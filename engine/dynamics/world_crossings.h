// What World's steps ask of a detection's manifolds about crossings (world.cpp,
// world_back_off.cpp): whether any pair crosses, which, and whether a pair that crossed at a
// rejected end of a step touches within its band at a state tried since.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "engine/collision/contact.h"

namespace rugosim::world_detail {

using BodyPairKey = std::pair<std::size_t, std::size_t>;

inline bool any_crossing(const std::vector<ContactManifold>& manifolds) {
  return std::any_of(manifolds.begin(), manifolds.end(), [](const ContactManifold& m) {
    return m.state() == PairState::kIntersecting;
  });
}

// Sorted, since the pipeline sorts its manifolds by (body_a, body_b).
inline std::vector<BodyPairKey> crossing_pairs(const std::vector<ContactManifold>& manifolds) {
  std::vector<BodyPairKey> pairs;
  for (const ContactManifold& m : manifolds) {
    if (m.state() == PairState::kIntersecting) pairs.emplace_back(m.body_a, m.body_b);
  }
  return pairs;
}

// Does a pair that crossed at the rejected end of the step touch within its band here?
inline bool touches_crossing_pair(const std::vector<ContactManifold>& manifolds,
                                  const std::vector<BodyPairKey>& pairs) {
  return std::any_of(manifolds.begin(), manifolds.end(), [&](const ContactManifold& m) {
    return m.state() == PairState::kContact &&
           std::binary_search(pairs.begin(), pairs.end(), BodyPairKey(m.body_a, m.body_b));
  });
}

}  // namespace rugosim::world_detail
