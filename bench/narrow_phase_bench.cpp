// Narrow phase per segment pair (paper §3.2, eqs. 3-4): nearest_points() and find_crossing()
// on the pairs the simulator meets most, a piece of a 64-segment circle against a side of a
// box whose leaf boxes overlap, placed separated, touching within a small band, or crossing
// slightly; and on generic random cubics, where the branch and bound does most of the work.
// Each family's baseline is a 16 x 16 sample-grid distance on the same pairs (32 evaluations
// and 256 squared distances: what a naive sampled narrow phase would cost, with none of the
// accuracy). One benchmark iteration handles one pair, cycling through 1024 pairs, so the time
// is the mean over that set; repetitions give the median. See ratio_reporter.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/collision/segment_crossing.h"
#include "engine/collision/segment_distance.h"
#include "engine/core/random.h"
#include "engine/core/transform.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/shapes.h"
#include "ratio_reporter.h"

namespace rugosim {
namespace {

constexpr std::size_t kPairs = 1024;

struct Pair {
  CubicSegment a, b;
};

enum class Placement { kSeparated, kTouching, kCrossing };

// A circle segment placed by a random rigid motion so that it faces a box side at the given
// gap (negative: overlapping), as a body resting on or falling onto a floor would.
std::vector<Pair> circle_on_box(Placement placement, std::uint64_t seed) {
  const PeriodicBSpline circle(circle_control_points(1.0, 64));
  const PeriodicBSpline box(box_control_points(4.0, 1.0, 64));
  Rng rng(seed);
  std::vector<Pair> pairs;
  pairs.reserve(kPairs);
  while (pairs.size() < kPairs) {
    const CubicSegment& side =
        box.segment(static_cast<std::size_t>(rng.uniform() * static_cast<double>(box.size())));
    const Vec2 tangent = side.bezier()[3] - side.bezier()[0];
    if (tangent.norm() == 0.0) continue;  // a corner's repeated control points
    const CubicSegment& arc = circle.segment(
        static_cast<std::size_t>(rng.uniform() * static_cast<double>(circle.size())));
    const double length = (arc.bezier()[3] - arc.bezier()[0]).norm();
    double gap = 0.0;
    switch (placement) {
      case Placement::kSeparated:
        gap = length * rng.uniform(0.01, 0.3);
        break;
      case Placement::kTouching:
        gap = length * rng.uniform(1e-4, 1e-2);
        break;
      case Placement::kCrossing:
        gap = -length * rng.uniform(1e-4, 5e-3);  // the arc's sagitta is 1.2% of its chord
        break;
    }
    const Vec2 outward = -perp(tangent.normalized());  // the box runs counter-clockwise
    const Vec2 q = side.point(rng.uniform(0.1, 0.9));
    const Vec2 p = arc.point(rng.uniform(0.2, 0.8));
    const Vec2 m = p.normalized();  // the circle's outward normal at p
    // Turn m onto −outward (facing the box), give or take a small tilt, then move p over q.
    const double angle =
        std::atan2(-outward.y(), -outward.x()) - std::atan2(m.y(), m.x()) + rng.uniform(-0.1, 0.1);
    const Transform2 turn(angle, Vec2::Zero());
    const Transform2 place(angle, q + gap * outward - turn.apply(p));
    pairs.push_back({arc.transformed(place), side});
  }
  return pairs;
}

std::vector<Pair> generic_pairs(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Pair> pairs;
  pairs.reserve(kPairs);
  const auto random_point = [&rng] { return Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)); };
  for (std::size_t i = 0; i < kPairs; ++i) {
    pairs.push_back({CubicSegment(random_point(), random_point(), random_point(), random_point()),
                     CubicSegment(random_point(), random_point(), random_point(), random_point())});
  }
  return pairs;
}

const std::vector<Pair>& family_pairs(int family) {
  static const std::array<std::vector<Pair>, 4> kFamilies{
      circle_on_box(Placement::kSeparated, 11), circle_on_box(Placement::kTouching, 12),
      circle_on_box(Placement::kCrossing, 13), generic_pairs(14)};
  return kFamilies[static_cast<std::size_t>(family)];
}

double grid_distance(const CubicSegment& a, const CubicSegment& b) {
  constexpr int kSamples = 16;
  std::array<Vec2, kSamples> pa, pb;
  for (int i = 0; i < kSamples; ++i) {
    const double t = i / double{kSamples - 1};
    pa[static_cast<std::size_t>(i)] = a.point(t);
    pb[static_cast<std::size_t>(i)] = b.point(t);
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Vec2& p : pa)
    for (const Vec2& q : pb)
      best = std::min(best, (p - q).squaredNorm());
  return std::sqrt(best);
}

void baseline(benchmark::State& state, int family) {
  const auto& pairs = family_pairs(family);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(grid_distance(pairs[i].a, pairs[i].b));
    i = (i + 1) % pairs.size();
  }
}

void nearest(benchmark::State& state, int family) {
  const auto& pairs = family_pairs(family);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(nearest_points(pairs[i].a, pairs[i].b));
    i = (i + 1) % pairs.size();
  }
}

void crossing(benchmark::State& state, int family) {
  const auto& pairs = family_pairs(family);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(find_crossing(pairs[i].a, pairs[i].b));
    i = (i + 1) % pairs.size();
  }
}

constexpr int kRepetitions = 5;

void register_family(const char* name, int family) {
  const std::string prefix(name);
  benchmark::RegisterBenchmark((prefix + "/baseline").c_str(), baseline, family)
      ->Repetitions(kRepetitions);
  benchmark::RegisterBenchmark((prefix + "/nearest_points").c_str(), nearest, family)
      ->Repetitions(kRepetitions);
  benchmark::RegisterBenchmark((prefix + "/find_crossing").c_str(), crossing, family)
      ->Repetitions(kRepetitions);
}

[[maybe_unused]] const bool kRegistered = [] {
  register_family("separated", 0);
  register_family("touching", 1);
  register_family("crossing", 2);
  register_family("generic", 3);
  return true;
}();

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  return rugosim::bench::run_with_ratios(argc, argv);
}
