#include "engine/core/disjoint_sets.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

// Against a brute-force labelling: random unions over 200 elements; after each, two elements
// share a root exactly when the brute force put them in the same component, and every root is
// the smallest member of its set.
TEST(DisjointSets, MatchesBruteForceComponentsWithSmallestRoots) {
  Rng rng(17);
  const std::size_t n = 200;
  DisjointSets sets;
  sets.reset(n);
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i)
    label[i] = i;
  for (int k = 0; k < 300; ++k) {
    const auto a = static_cast<std::size_t>(rng.uniform() * n);
    const auto b = static_cast<std::size_t>(rng.uniform() * n);
    sets.unite(a, b);
    const std::size_t from = label[b], to = label[a];
    for (std::size_t& l : label) {
      if (l == from) l = to;
    }
    if (k % 30 != 0) continue;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t smallest = i;
      for (std::size_t j = 0; j < n; ++j) {
        if (label[j] == label[i]) smallest = std::min(smallest, j);
        if (j % 7 == 0) {
          EXPECT_EQ(sets.root(i) == sets.root(j), label[i] == label[j]);
        }
      }
      EXPECT_EQ(sets.root(i), smallest);
    }
  }
  sets.reset(3);
  EXPECT_EQ(sets.root(2), 2u);
}

}  // namespace
}  // namespace rugosim
