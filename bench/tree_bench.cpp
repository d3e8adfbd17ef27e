// AOBB tree benchmarks (paper §3.1-3.2): the box overlap test, the tree-versus-tree query of two
// bodies in contact against testing all leaf pairs, and building a tree. Each family has a
// "baseline" variant measured in the same run; see ratio_reporter.h.
#include <cstdint>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/collision/aobb_tree.h"
#include "engine/collision/obb_overlap.h"
#include "engine/core/aabb.h"
#include "engine/core/random.h"
#include "engine/geometry/shapes.h"
#include "ratio_reporter.h"

namespace rugosim {
namespace {

constexpr std::size_t kBoxPairs = 1024;

// Random box pairs of unit size, placed so that about half of them overlap: the branch in the
// test is then as unpredictable as in a tree descent.
std::vector<Obb> random_boxes(std::size_t count) {
  Rng rng(7);
  std::vector<Obb> boxes;
  boxes.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    Obb box;
    const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
    box.center = Vec2(rng.uniform(0.0, 3.0), rng.uniform(0.0, 3.0));
    box.axis_x = Vec2(std::cos(angle), std::sin(angle));
    box.axis_y = perp(box.axis_x);
    box.half_extents = Vec2(rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0));
    boxes.push_back(box);
  }
  return boxes;
}

void set_tests_per_iteration(benchmark::State& state, std::size_t tests) {
  // items_per_second: 1e9 / items_per_second is the time of one test in ns.
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(tests));
}

// Baseline: the axis-aligned boxes around the same pairs.
void box_test_baseline(benchmark::State& state) {
  const auto a = random_boxes(kBoxPairs), b = random_boxes(2 * kBoxPairs);
  std::vector<Aabb> aa, bb;
  for (std::size_t i = 0; i < kBoxPairs; ++i) {
    Aabb x, y;
    for (const Vec2& c : a[i].corners())
      x.extend(c);
    for (const Vec2& c : b[kBoxPairs + i].corners())
      y.extend(c);
    aa.push_back(x);
    bb.push_back(y);
  }
  for (auto _ : state) {
    int hits = 0;
    for (std::size_t i = 0; i < kBoxPairs; ++i)
      hits += aa[i].overlaps(bb[i]) ? 1 : 0;
    benchmark::DoNotOptimize(hits);
  }
  set_tests_per_iteration(state, kBoxPairs);
}

void box_test_obb(benchmark::State& state) {
  const auto a = random_boxes(kBoxPairs), b = random_boxes(2 * kBoxPairs);
  for (auto _ : state) {
    int hits = 0;
    for (std::size_t i = 0; i < kBoxPairs; ++i)
      hits += obb_overlap(a[i], b[kBoxPairs + i]) ? 1 : 0;
    benchmark::DoNotOptimize(hits);
  }
  set_tests_per_iteration(state, kBoxPairs);
}

// As the tree query uses it: the other body's box is placed in this body's frame first.
void box_test_placed_obb(benchmark::State& state) {
  const auto a = random_boxes(kBoxPairs), b = random_boxes(2 * kBoxPairs);
  const Transform2 x(0.3, Vec2(0.1, -0.2));
  for (auto _ : state) {
    int hits = 0;
    for (std::size_t i = 0; i < kBoxPairs; ++i)
      hits += obb_overlap(a[i], b[kBoxPairs + i].transformed(x)) ? 1 : 0;
    benchmark::DoNotOptimize(hits);
  }
  set_tests_per_iteration(state, kBoxPairs);
}

struct Body {
  PeriodicBSpline curve;
  ToleranceProfile tolerances;
  AobbTree tree;
  Body(std::vector<Vec2> points, double lambda)
      : curve(std::move(points)),
        tolerances(std::vector<double>(curve.size(), lambda)),
        tree(curve, tolerances) {}
};

// Two bodies touching along a stretch, each with n segments; b_to_a places B in A's frame.
struct ContactScene {
  Body a, b;
  Transform2 b_to_a;
};

// A unit circle resting on a 4 x 0.5 box (its lowest knot on the box's top), with bands of
// 0.005 m each: the bands meet along about 0.28 m of the box.
ContactScene circle_on_box(std::size_t n) {
  return {Body(box_control_points(4.0, 0.5, n), 0.005), Body(circle_control_points(1.0, n), 0.005),
          Transform2(0.0, Vec2(0.0, 1.25))};
}

// Two irregular blobs of radius about 1 pushed a little into each other.
ContactScene two_blobs(std::size_t n) {
  Body a(blob_control_points(1.0, 0.4, n, 5), 0.005);
  Body b(blob_control_points(1.0, 0.4, n, 6), 0.005);
  // Slide B (turned by 2 rad) in along x until the first leaf pairs appear, then 4 cm further.
  double x = 4.0;
  std::vector<LeafPair> pairs;
  while (x > 0.0) {
    pairs.clear();
    a.tree.query(b.tree, Transform2(2.0, Vec2(x, 0.0)), pairs);
    if (!pairs.empty()) break;
    x -= 0.01;
  }
  return {std::move(a), std::move(b), Transform2(2.0, Vec2(x - 0.04, 0.0))};
}

// Baseline: every leaf box of A against every placed leaf box of B.
void all_pairs(benchmark::State& state, const ContactScene& scene) {
  const std::size_t na = scene.a.tree.segment_count(), nb = scene.b.tree.segment_count();
  std::vector<Obb> placed(nb);
  std::vector<LeafPair> out;
  out.reserve(na * nb);
  for (auto _ : state) {
    out.clear();
    for (std::size_t j = 0; j < nb; ++j)
      placed[j] = scene.b.tree.leaf_box(j).transformed(scene.b_to_a);
    for (std::uint32_t i = 0; i < na; ++i) {
      const Obb& box = scene.a.tree.leaf_box(i);
      for (std::uint32_t j = 0; j < nb; ++j) {
        if (obb_overlap(box, placed[j])) out.push_back({i, j});
      }
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["pairs"] = static_cast<double>(out.size());
}

void tree_query(benchmark::State& state, const ContactScene& scene) {
  std::vector<LeafPair> out;
  for (auto _ : state) {
    out.clear();
    scene.a.tree.query(scene.b.tree, scene.b_to_a, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["pairs"] = static_cast<double>(out.size());
  state.counters["depth"] = scene.a.tree.depth();
}

void query_baseline(benchmark::State& state) {
  all_pairs(state, circle_on_box(static_cast<std::size_t>(state.range(0))));
}
void query_tree(benchmark::State& state) {
  tree_query(state, circle_on_box(static_cast<std::size_t>(state.range(0))));
}
void query_blobs_baseline(benchmark::State& state) {
  all_pairs(state, two_blobs(static_cast<std::size_t>(state.range(0))));
}
void query_blobs_tree(benchmark::State& state) {
  tree_query(state, two_blobs(static_cast<std::size_t>(state.range(0))));
}

// Building a tree, against building the curve and tolerance profile it is made from.
void build_baseline(benchmark::State& state) {
  const auto points = blob_control_points(1.0, 0.4, static_cast<std::size_t>(state.range(0)), 5);
  for (auto _ : state) {
    PeriodicBSpline curve(points);
    ToleranceProfile tolerances(std::vector<double>(curve.size(), 0.005));
    benchmark::DoNotOptimize(curve.segments().data());
    benchmark::DoNotOptimize(tolerances.segment_tolerances().data());
  }
}

void build_tree(benchmark::State& state) {
  const PeriodicBSpline curve(
      blob_control_points(1.0, 0.4, static_cast<std::size_t>(state.range(0)), 5));
  std::vector<double> lambda(curve.size());
  Rng rng(9);
  for (double& l : lambda)
    l = rng.uniform(0.001, 0.01);  // rough and smooth segments: λ(t) maxima are computed
  const ToleranceProfile tolerances(lambda);
  for (auto _ : state) {
    AobbTree tree(curve, tolerances);
    benchmark::DoNotOptimize(tree.nodes().data());
  }
}

#define RUGOSIM_SIZES RangeMultiplier(4)->Range(16, 1024)
BENCHMARK(box_test_baseline)->Name("box_test/baseline");
BENCHMARK(box_test_obb)->Name("box_test/obb");
BENCHMARK(box_test_placed_obb)->Name("box_test/place_and_obb");
BENCHMARK(query_baseline)->Name("query/baseline")->RUGOSIM_SIZES;
BENCHMARK(query_tree)->Name("query/tree")->RUGOSIM_SIZES;
BENCHMARK(query_blobs_baseline)->Name("query_blobs/baseline")->RUGOSIM_SIZES;
BENCHMARK(query_blobs_tree)->Name("query_blobs/tree")->RUGOSIM_SIZES;
BENCHMARK(build_baseline)->Name("build/baseline")->RUGOSIM_SIZES;
BENCHMARK(build_tree)->Name("build/tree")->RUGOSIM_SIZES;

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  return rugosim::bench::run_with_ratios(argc, argv);
}
