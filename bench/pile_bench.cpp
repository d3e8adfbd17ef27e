// Piles of 10, 50, 200 and 1,000 irregular bodies (24 segments, σ = 3 mm) dropped into an open
// box and left for 5 simulated seconds, long enough for a settled pile to sleep
// (tests/support/pile_scene.h; scenes/pile_*.json are the same piles): rugosim's wall time per
// simulated second at the draft and normal presets, on one thread and on every CPU, against
// Box2D 2.4.1 on the same scene measured in the same run (bench/box2d_pile.h: each body a
// compound of convex pieces approximating the same outline). The baseline is Box2D with one
// outline point per B-spline segment (pile/box2d_1_sample: about 7 pieces per blob, the faster
// and so the stricter one); the ratio column reads "rugosim time / Box2D time".
//
// rugosim advances frame by frame at 30 fps, as `rugosim simulate` does. Box2D steps at 60 Hz
// with 8 velocity and 3 position iterations (its testbed's settings), in units where the pile's
// 0.1 m bodies are 1 unit (length_scale 10: Box2D's tolerances are absolute and tuned for
// bodies of 0.1 to 10 m). Every rugosim contact here has μ = k·λ = 100/m · 2.7 mm = 0.27
// (λ_min = 0), which Box2D gets on every fixture, with the same ε = 0.3 and densities.
//
// pile/normal_micro_collisions_* is normal as it was before the presets rested contacts at
// mid-step (mid_step_rest 0, rest_stride 1: resting contact by the paper's micro-collisions
// alone): what mid-step rest and the rest steps it allows save. pile/normal_hard_rest_* is
// normal with the exact mid-step solve in place of its soft one (soft_rest 0, as the preset was
// before stop 45): what the soft solve, and the sleep it brings, save.
//
// Counters: wall_per_sim_s; ns_per_body_step, the wall time per awake body and step (how cost
// grows with the work); detection_s, the collision detection's share (World::profile); asleep_at,
// when every body slept (−1: not within 5 s); creep_bands, the largest net displacement of a
// body over its last second awake, resting, in its contact bands (tests/support/rest_creep.h),
// with resting, how many bodies rested through that second; and the step statistics.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "box2d_pile.h"
#include "engine/core/thread_pool.h"
#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/world.h"
#include "ratio_reporter.h"
#include "support/pile_scene.h"
#include "support/rest_creep.h"

namespace rugosim {
namespace {

constexpr double kSimulated = 5.0;  // s
constexpr double kFrame = 1.0 / 30.0;
constexpr double kBox2dStep = 1.0 / 60.0;

testing::PileSpec spec_for(std::int64_t bodies) {
  testing::PileSpec spec;
  spec.bodies = static_cast<std::size_t>(bodies);
  return spec;
}

// Wall seconds per simulated second, as a counter next to the time per 5 s run.
void report_rate(benchmark::State& state) {
  state.counters["wall_per_sim_s"] = benchmark::Counter(
      kSimulated, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

struct RugosimRun {
  std::string preset;
  int threads = 1;
  bool sleeping = true;
  int rest_stride = 0;     // 0: the preset's
  int mid_step_rest = -1;  // -1: the preset's
  int soft_rest = -1;      // the soft_rest knob (soft_rest.h); -1: the preset's
};

void pile_rugosim(benchmark::State& state, const RugosimRun& run) {
  const std::vector<testing::PileBody> scene = testing::pile_scene(spec_for(state.range(0)));
  Accuracy accuracy = *accuracy_preset(run.preset);
  if (run.soft_rest >= 0) accuracy.soft_rest = run.soft_rest;
  WorldSettings settings = with_accuracy(WorldSettings{}, accuracy);
  settings.sleep.enabled = run.sleeping;
  if (run.rest_stride > 0) settings.rest_stride = run.rest_stride;
  if (run.mid_step_rest >= 0) settings.mid_step_rest = run.mid_step_rest != 0;
  settings.record_events = false;
  settings.threads = run.threads;
  StepStats stats;
  StepProfile profile;
  double asleep_at = -1.0;
  std::size_t awake = 0;
  testing::RestCreep creep;
  for (auto _ : state) {
    state.PauseTiming();
    testing::RestCreepTracker creep_tracker(static_cast<int>(1.0 / kFrame + 0.5));
    World world(settings);
    for (const testing::PileBody& b : scene)
      world.add_body(RigidBody(b.desc), b.name);
    asleep_at = -1.0;
    state.ResumeTiming();
    const auto frames = static_cast<int>(kSimulated / kFrame + 0.5);
    for (int k = 1; k <= frames; ++k) {
      world.advance_to(k * kFrame);
      // O(n) per frame, next to a frame's steps: part of what a caller pays.
      if (asleep_at < 0.0) {
        bool all = true;
        for (std::size_t i = 0; i < world.body_count() && all; ++i)
          all = world.body(i).fixed() || world.asleep(i);
        if (all) asleep_at = world.time();
      }
      state.PauseTiming();
      creep_tracker.record(world);
      state.ResumeTiming();
    }
    state.PauseTiming();
    creep = creep_tracker.result();
    stats = world.stats();
    profile = world.profile();
    awake = 0;
    for (std::size_t i = 0; i < world.body_count(); ++i)
      awake += !world.body(i).fixed() && !world.asleep(i) ? 1u : 0u;
    state.ResumeTiming();
  }
  report_rate(state);
  state.counters["ns_per_body_step"] = benchmark::Counter(
      1e-9 * static_cast<double>(stats.body_steps),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["detection_s"] = profile.detection;
  state.counters["resolution_s"] = profile.resolution;
  state.counters["asleep_at"] = asleep_at;
  state.counters["awake"] = static_cast<double>(awake);
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["body_steps"] = static_cast<double>(stats.body_steps);
  state.counters["contacts"] = static_cast<double>(stats.contacts);
  state.counters["fallbacks"] = static_cast<double>(stats.fallbacks);
  state.counters["crossings"] = static_cast<double>(stats.crossings);
  // Resting bodies' net displacement over their last second awake, in contact bands (issue 14:
  // at most 1), and how many rested through it.
  state.counters["creep_bands"] = creep.worst_ratio;
  state.counters["resting"] = static_cast<double>(creep.resting);
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

void add(const std::string& name, std::int64_t bodies, int repetitions,
         const std::function<void(benchmark::State&)>& body) {
  benchmark::RegisterBenchmark(name.c_str(), body)
      ->Arg(bodies)
      ->Iterations(1)
      ->Repetitions(repetitions)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

void register_all() {
  const int cpus = available_cpus();
  for (const std::int64_t n : {10, 50, 200, 1000}) {
    // One iteration is a whole 5 s run; repetitions give medians (fewer for the big piles).
    const int repetitions = n <= 50 ? 5 : n == 200 ? 3 : 1;
    add("pile/box2d_1_sample", n, repetitions, [](benchmark::State& s) { pile_box2d(s, 1); });
    // A finer outline (2 points per segment, about 15 pieces per blob, mass within 0.4%).
    if (n <= 200) {
      add("pile/box2d_2_samples", n, repetitions, [](benchmark::State& s) { pile_box2d(s, 2); });
    }
    for (const std::string preset : {"draft", "normal"}) {
      std::vector<int> thread_counts = {1};
      if (cpus > 1) thread_counts.push_back(cpus);
      for (const int threads : thread_counts) {
        const RugosimRun run{preset, threads, true};
        add("pile/" + preset + "_" + std::to_string(threads) +
                (threads == 1 ? "_thread" : "_threads"),
            n, repetitions, [run](benchmark::State& s) { pile_rugosim(s, run); });
      }
    }
    // What mid-step rest and its rest steps save: normal with resting contact by
    // micro-collisions alone and every step near contact at max_step, as before.
    if (n <= 200) {
      for (const int threads : {1, cpus}) {
        const std::string suffix =
            std::to_string(threads) + (threads == 1 ? "_thread" : "_threads");
        const RugosimRun run{"normal", threads, true, 1, 0};
        add("pile/normal_micro_collisions_" + suffix, n, repetitions,
            [run](benchmark::State& s) { pile_rugosim(s, run); });
        if (cpus == 1) break;
      }
    }
    // The exact mid-step solve in place of the preset's soft one (soft_rest 0): piles that keep
    // creeping and seldom sleep.
    if (n <= 200) {
      for (const int threads : {1, cpus}) {
        const std::string suffix =
            std::to_string(threads) + (threads == 1 ? "_thread" : "_threads");
        RugosimRun run{"normal", threads, true};
        run.soft_rest = 0;
        add("pile/normal_hard_rest_" + suffix, n, repetitions,
            [run](benchmark::State& s) { pile_rugosim(s, run); });
        if (cpus == 1) break;
      }
    }
    // What sleeping saves (awake for the whole 5 s: the big pile is left out).
    if (n <= 200) {
      const RugosimRun run{"normal", cpus, false};
      add("pile/normal_no_sleep", n, 1, [run](benchmark::State& s) { pile_rugosim(s, run); });
    }
  }
}

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  rugosim::register_all();
  rugosim::bench::set_baseline_variant("pile", "box2d_1_sample");
  return rugosim::bench::run_with_ratios(argc, argv);
}
