#include "engine/collision/broad_phase.h"

#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

std::vector<BodyPair> all_pairs(const std::vector<BroadPhaseProxy>& proxies) {
  std::vector<BodyPair> out;
  for (std::uint32_t i = 0; i < proxies.size(); ++i) {
    for (std::uint32_t j = i + 1; j < proxies.size(); ++j) {
      if (proxies[i].box.overlaps(proxies[j].box) && pair_can_interact(proxies[i], proxies[j])) {
        out.push_back({i, j});
      }
    }
  }
  return out;
}

Aabb box_at(const Vec2& centre, const Vec2& half) {
  Aabb box;
  box.extend(centre - half);
  box.extend(centre + half);
  return box;
}

// Random layouts: uniform spreads, piles on a line, clusters, tiny and huge boxes, touching
// and identical boxes, with fixed and sleeping bodies mixed in.
std::vector<BroadPhaseProxy> random_layout(Rng& rng) {
  const auto count = static_cast<std::size_t>(rng.uniform(0.0, 300.0));
  const int kind = static_cast<int>(rng.uniform(0.0, 4.0));
  const double world = std::pow(10.0, rng.uniform(-2.0, 3.0));
  std::vector<BroadPhaseProxy> proxies(count);
  for (auto& p : proxies) {
    Vec2 centre(rng.uniform(0.0, world), rng.uniform(0.0, world));
    if (kind == 1) centre.y() = 0.0;  // all on one line
    if (kind == 2) centre = Vec2(std::floor(centre.x() / world * 5) * world / 5, centre.y());
    const double size = world * std::pow(10.0, rng.uniform(-3.0, -0.5));
    Vec2 half(size * rng.uniform(0.1, 1.0), size * rng.uniform(0.1, 1.0));
    if (kind == 3 && rng.uniform() < 0.3) half = Vec2::Zero();  // degenerate boxes
    p.box = box_at(centre, half);
    p.fixed = rng.uniform() < 0.2;
    p.asleep = !p.fixed && rng.uniform() < 0.2;
  }
  // Exactly touching and exactly identical boxes.
  if (count >= 4) {
    proxies[1].box = proxies[0].box;
    proxies[3].box = proxies[2].box;
    const double w = proxies[2].box.extent().x();
    proxies[3].box.min.x() += w;
    proxies[3].box.max.x() += w;  // shares an edge with proxy 2
  }
  return proxies;
}

TEST(BroadPhase, ReturnsExactlyTheAllPairsResultOnRandomLayouts) {
  Rng rng(41);
  SweepAndPrune sweep;
  std::size_t total = 0;
  for (int layout = 0; layout < 3000; ++layout) {
    auto proxies = random_layout(rng);
    ASSERT_EQ(sweep.find_pairs(proxies), all_pairs(proxies)) << "layout " << layout;
    total += all_pairs(proxies).size();
  }
  EXPECT_GT(total, 10000u);  // the layouts do produce pairs to compare
}

TEST(BroadPhase, KeepsAgreeingWhileBodiesMoveBetweenCalls) {
  // The sorted order is reused between calls: moving the boxes must not lose pairs.
  Rng rng(42);
  SweepAndPrune sweep;
  std::vector<BroadPhaseProxy> proxies(400);
  std::vector<Vec2> velocity(proxies.size());
  for (std::size_t i = 0; i < proxies.size(); ++i) {
    proxies[i].box = box_at(Vec2(rng.uniform(0, 100), rng.uniform(0, 100)), Vec2(1.5, 1.0));
    velocity[i] = Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1));
  }
  for (int frame = 0; frame < 100; ++frame) {
    for (std::size_t i = 0; i < proxies.size(); ++i) {
      proxies[i].box.min += velocity[i];
      proxies[i].box.max += velocity[i];
    }
    ASSERT_EQ(sweep.find_pairs(proxies), all_pairs(proxies)) << "frame " << frame;
  }
}

TEST(BroadPhase, FixedPairsAndSleepingPairsAreLeftOut) {
  std::vector<BroadPhaseProxy> proxies(4);
  for (auto& p : proxies)
    p.box = box_at(Vec2::Zero(), Vec2(1, 1));
  proxies[0].fixed = proxies[1].fixed = true;  // fixed-fixed: never
  proxies[2].asleep = true;                    // sleeping vs fixed: never
  SweepAndPrune sweep;
  const auto pairs = sweep.find_pairs(proxies);
  // Body 3 moves: it meets everyone; 0-1, 0-2, 1-2 cannot interact.
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{0, 3}, {1, 3}, {2, 3}}));
}

TEST(BroadPhase, EmptyAndSingleBodyWorlds) {
  SweepAndPrune sweep;
  EXPECT_TRUE(sweep.find_pairs({}).empty());
  std::vector<BroadPhaseProxy> one(1);
  one[0].box = box_at(Vec2::Zero(), Vec2(1, 1));
  EXPECT_TRUE(sweep.find_pairs(one).empty());
}

}  // namespace
}  // namespace rugosim
