// Disjoint sets (union-find) over 0..n−1, for islands and clusters of bodies. Unions keep the
// smaller index as the root, so every set's root is its smallest member: deterministic, and a
// natural id for the set.
#pragma once

#include <cstddef>
#include <vector>

namespace rugosim {

class DisjointSets {
 public:
  // Makes n singletons, reusing the storage.
  void reset(std::size_t n) {
    // clear + push_back rather than resize: GCC 12 warns falsely on vector::resize here.
    parent_.clear();
    parent_.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      parent_.push_back(i);
  }

  std::size_t root(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];  // path halving
      i = parent_[i];
    }
    return i;
  }

  void unite(std::size_t a, std::size_t b) {
    const std::size_t ra = root(a);
    const std::size_t rb = root(b);
    if (ra < rb) {
      parent_[rb] = ra;
    } else if (rb < ra) {
      parent_[ra] = rb;
    }
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace rugosim
