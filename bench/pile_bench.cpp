// Piles of 10, 50 and 200 irregular bodies (24 segments, σ = 3 mm) dropped into an open box and
// left to settle for 3 simulated seconds (tests/support/pile_scene.h, the scene of the pile
// test): rugosim's wall time per simulated second, with its step statistics, against Box2D
// 2.4.1 on the same scene (bench/box2d_pile.h: each body a compound of convex pieces
// approximating the same outline), measured in the same run. Box2D is the baseline: the ratio
// column reads "rugosim time / Box2D time".
//
// Box2D steps at 60 Hz with 8 velocity and 3 position iterations (its testbed's settings), in
// units where the pile's 0.1 m bodies are 1 unit (length_scale 10: Box2D's tolerances are
// absolute and tuned for bodies of 0.1 to 10 m; at 1:1 its 1 cm polygon skin and 0.1 m box
// margin are a tenth of a body and the 200-body pile did not finish one simulated second in 25
// minutes), with the outline sampled at 2 points per segment (about 15 convex pieces per
// concave blob, mass within 0.4% of rugosim's: Box2D's cost grows with the square of the
// pieces per body, since each touching pair of bodies has a contact per pair of pieces).
// Every rugosim contact here has μ = k·λ = 100/m · 2.7 mm = 0.27 (λ_min = 0), which Box2D gets
// on every fixture, with the same ε = 0.3 and densities. A third variant runs rugosim with
// sleeping off, to show what sleeping saves.
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "box2d_pile.h"
#include "engine/dynamics/world.h"
#include "ratio_reporter.h"
#include "support/pile_scene.h"

namespace rugosim {
namespace {

constexpr double kSimulated = 3.0;  // s
constexpr double kBox2dStep = 1.0 / 60.0;

testing::PileSpec spec_for(std::int64_t bodies) {
  testing::PileSpec spec;
  spec.bodies = static_cast<std::size_t>(bodies);
  return spec;
}

// Wall seconds per simulated second, as a counter next to the time per 3 s settle.
void report_rate(benchmark::State& state) {
  state.counters["wall_per_sim_s"] = benchmark::Counter(
      kSimulated, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void pile_rugosim(benchmark::State& state, bool sleeping) {
  const testing::PileSpec spec = spec_for(state.range(0));
  const std::vector<testing::PileBody> scene = testing::pile_scene(spec);
  WorldSettings settings;
  settings.sleep.enabled = sleeping;
  settings.record_events = false;
  StepStats stats;
  std::size_t asleep = 0;
  for (auto _ : state) {
    state.PauseTiming();
    World world(settings);
    for (const testing::PileBody& b : scene)
      world.add_body(RigidBody(b.desc), b.name);
    state.ResumeTiming();
    world.advance_to(kSimulated);
    state.PauseTiming();
    stats = world.stats();
    asleep = 0;
    for (std::size_t i = 0; i < world.body_count(); ++i)
      asleep += world.asleep(i) ? 1u : 0u;
    state.ResumeTiming();
  }
  report_rate(state);
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["bisections"] = static_cast<double>(stats.bisections);
  state.counters["collisions"] = static_cast<double>(stats.collisions);
  state.counters["contacts"] = static_cast<double>(stats.contacts);
  state.counters["fallbacks"] = static_cast<double>(stats.fallbacks);
  state.counters["rigid_clusters"] = static_cast<double>(stats.rigid_clusters);
  state.counters["crossings"] = static_cast<double>(stats.crossings);
  state.counters["asleep"] = static_cast<double>(asleep);
}

void pile_box2d(benchmark::State& state, int samples_per_segment) {
  const testing::PileSpec spec = spec_for(state.range(0));
  const std::vector<testing::PileBody> scene = testing::pile_scene(spec);
  const double mu = WorldSettings{}.friction_gain * 0.9 * spec.sigma;
  bench::Box2dPileOptions options{mu, spec.restitution};
  options.length_scale = 10.0;
  options.samples_per_segment = samples_per_segment;
  std::size_t awake = 0, fixtures = 0;
  for (auto _ : state) {
    state.PauseTiming();
    bench::Box2dPile pile(scene, options);
    state.ResumeTiming();
    const int steps = static_cast<int>(kSimulated / kBox2dStep + 0.5);
    for (int i = 0; i < steps; ++i)
      pile.step(kBox2dStep);
    state.PauseTiming();
    awake = pile.awake_bodies();
    fixtures = pile.fixture_count();
    state.ResumeTiming();
  }
  report_rate(state);
  state.counters["awake"] = static_cast<double>(awake);
  state.counters["fixtures"] = static_cast<double>(fixtures);
}

void register_all() {
  for (const std::int64_t n : {10, 50, 200}) {
    // One iteration is a whole 3 s settle; repetitions give a median for the small piles.
    const int repetitions = n <= 50 ? 3 : 1;
    benchmark::RegisterBenchmark("pile/baseline", [](benchmark::State& s) { pile_box2d(s, 2); })
        ->Arg(n)
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->Unit(benchmark::kMillisecond);
    // Box2D with a coarser outline (1 point per segment, about 7 pieces per blob, mass 1.5%
    // low): faster, less faithful.
    benchmark::RegisterBenchmark("pile/box2d_1_sample",
                                 [](benchmark::State& s) { pile_box2d(s, 1); })
        ->Arg(n)
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("pile/rugosim", [](benchmark::State& s) { pile_rugosim(s, true); })
        ->Arg(n)
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("pile/rugosim_no_sleep",
                                 [](benchmark::State& s) { pile_rugosim(s, false); })
        ->Arg(n)
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  rugosim::register_all();
  return rugosim::bench::run_with_ratios(argc, argv);
}
