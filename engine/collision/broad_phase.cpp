#include "engine/collision/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace rugosim {

namespace {

// Variance of the box centres along an axis: sweeping along the axis where they spread most
// keeps the intervals that overlap on it, and so the candidates, few.
double spread(std::span<const BroadPhaseProxy> proxies, int axis) {
  double sum = 0.0, sum_sq = 0.0;
  for (const BroadPhaseProxy& p : proxies) {
    const double c = p.box.center()[axis];
    sum += c;
    sum_sq += c * c;
  }
  const double n = static_cast<double>(proxies.size());
  return sum_sq / n - (sum / n) * (sum / n);
}

}  // namespace

const std::vector<BodyPair>& SweepAndPrune::find_pairs(std::span<const BroadPhaseProxy> proxies) {
  pairs_.clear();
  const auto count = static_cast<std::uint32_t>(proxies.size());
  if (count < 2) return pairs_;

  // Keep the current axis unless the other one is clearly better: flipping between two nearly
  // equal axes would throw the kept order away every call.
  const double along_x = spread(proxies, 0), along_y = spread(proxies, 1);
  int axis = axis_;
  if (order_.size() != count) {
    axis = along_x >= along_y ? 0 : 1;
  } else if ((axis_ == 0 ? along_y : along_x) > 2.0 * (axis_ == 0 ? along_x : along_y)) {
    axis = 1 - axis_;
  }
  if (order_.size() != count || axis != axis_) {
    order_.resize(count);
    std::iota(order_.begin(), order_.end(), 0u);
    axis_ = axis;
  }
  // Ties broken by index so that the order, and hence the work, is deterministic.
  auto before = [&](std::uint32_t i, std::uint32_t j) {
    const double mi = proxies[i].box.min[axis_], mj = proxies[j].box.min[axis_];
    return mi < mj || (mi == mj && i < j);
  };
  // Insertion sort: linear when the previous order is nearly right (coherent motion), and
  // std::sort's n log n when it is not.
  std::size_t inversions = 0;
  for (std::size_t k = 1; k < order_.size(); ++k) {
    const std::uint32_t moving = order_[k];
    std::size_t slot = k;
    while (slot > 0 && before(moving, order_[slot - 1])) {
      order_[slot] = order_[slot - 1];
      --slot;
      if (++inversions > 8 * order_.size()) break;
    }
    order_[slot] = moving;
    if (inversions > 8 * order_.size()) {
      std::sort(order_.begin(), order_.end(), before);
      break;
    }
  }

  // The boxes in sweep order, side by side in memory: the inner loop below runs over a few
  // neighbours of each box, and reading them through order_ cost a cache miss each.
  const int other = 1 - axis_;
  swept_.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t i = order_[k];
    const BroadPhaseProxy& p = proxies[i];
    swept_[k] = {p.box.min[axis_], p.box.max[axis_], p.box.min[other], p.box.max[other], i,
                 proxy_moves(p)};
  }
  for (std::size_t k = 0; k < count; ++k) {
    const Swept& bi = swept_[k];
    for (std::size_t m = k + 1; m < count; ++m) {
      const Swept& bj = swept_[m];
      if (bj.lo > bi.hi) break;  // sorted: nothing further can overlap i
      if (bj.other_lo > bi.other_hi || bi.other_lo > bj.other_hi) continue;
      if (!bi.moves && !bj.moves) continue;  // pair_can_interact
      pairs_.push_back(bi.index < bj.index ? BodyPair{bi.index, bj.index}
                                           : BodyPair{bj.index, bi.index});
    }
  }
  // Sorted by (a, b): a counting sort on a, then each body's few partners by insertion, linear
  // in the pairs where a general sort was the sweep's most expensive part.
  starts_.assign(count + 1, 0);
  for (const BodyPair& p : pairs_)
    ++starts_[p.a + 1];
  for (std::size_t i = 0; i < count; ++i)
    starts_[i + 1] += starts_[i];
  sorted_.resize(pairs_.size());
  cursor_.assign(starts_.begin(), starts_.end() - 1);
  for (const BodyPair& p : pairs_)
    sorted_[cursor_[p.a]++] = p;
  for (std::size_t i = 0; i < count; ++i) {
    const auto first = sorted_.begin() + starts_[i];
    const auto last = sorted_.begin() + starts_[i + 1];
    for (auto it = first; it != last; ++it) {
      const BodyPair moving = *it;
      auto slot = it;
      for (; slot != first && (slot - 1)->b > moving.b; --slot)
        *slot = *(slot - 1);
      *slot = moving;
    }
  }
  std::swap(pairs_, sorted_);
  return pairs_;
}

}  // namespace rugosim
