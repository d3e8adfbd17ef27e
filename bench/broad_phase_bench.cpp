// Broad phase: sort-and-sweep against all-pairs box tests, for 100, 1,000 and 10,000 bodies
// spread over a square at the density of a busy scene (each body overlapping a few others).
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/collision/broad_phase.h"
#include "engine/core/random.h"
#include "ratio_reporter.h"

namespace rugosim {
namespace {

std::vector<BroadPhaseProxy> layout(std::size_t count) {
  Rng rng(5);
  // Side grows like sqrt(count): the number of neighbours per body stays the same.
  const double side = 4.0 * std::sqrt(static_cast<double>(count));
  std::vector<BroadPhaseProxy> proxies(count);
  for (auto& p : proxies) {
    const Vec2 centre(rng.uniform(0, side), rng.uniform(0, side));
    const Vec2 half(rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5));
    p.box.extend(centre - half);
    p.box.extend(centre + half);
    p.fixed = rng.uniform() < 0.05;
  }
  return proxies;
}

void broad_baseline(benchmark::State& state) {
  const auto proxies = layout(static_cast<std::size_t>(state.range(0)));
  std::vector<BodyPair> pairs;
  for (auto _ : state) {
    pairs.clear();
    for (std::uint32_t i = 0; i < proxies.size(); ++i) {
      for (std::uint32_t j = i + 1; j < proxies.size(); ++j) {
        if (proxies[i].box.overlaps(proxies[j].box) && pair_can_interact(proxies[i], proxies[j])) {
          pairs.push_back({i, j});
        }
      }
    }
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

// Bodies that drift a little each call, as between frames: the kept order makes the sort cheap.
void broad_sweep_coherent(benchmark::State& state) {
  auto proxies = layout(static_cast<std::size_t>(state.range(0)));
  SweepAndPrune sweep;
  Rng rng(6);
  std::size_t found = 0;
  for (auto _ : state) {
    state.PauseTiming();
    for (auto& p : proxies) {
      const Vec2 step(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05));
      p.box.min += step;
      p.box.max += step;
    }
    state.ResumeTiming();
    found = sweep.find_pairs(proxies).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["pairs"] = static_cast<double>(found);
}

// A fresh sweep each time: the sort starts from scratch. The same boxes every iteration let
// the branch predictor learn the sweep, so this flatters it; sweep_coherent, whose boxes change
// between calls, is the figure to quote.
void broad_sweep_cold(benchmark::State& state) {
  const auto proxies = layout(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    SweepAndPrune sweep;
    benchmark::DoNotOptimize(sweep.find_pairs(proxies).data());
  }
}

BENCHMARK(broad_baseline)
    ->Name("broad/baseline")
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(broad_sweep_coherent)
    ->Name("broad/sweep_coherent")
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(broad_sweep_cold)
    ->Name("broad/sweep_cold")
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  return rugosim::bench::run_with_ratios(argc, argv);
}
