// Accuracy presets and knobs (accuracy.h): "normal" is exactly the World's defaults (so the
// preset changes nothing of what the defaults give), draft is coarser than normal and precise
// finer on every knob, every knob reaches the World setting it names, and out-of-range knobs
// are refused with the knob's name and range.
#include "engine/dynamics/accuracy.h"

#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

TEST(Accuracy, NormalIsTheWorldsDefaults) {
  const WorldSettings defaults;
  const WorldSettings normal = with_accuracy(WorldSettings{}, *accuracy_preset("normal"));
  EXPECT_EQ(*accuracy_preset("normal"), Accuracy{});
  EXPECT_EQ(normal.max_step, defaults.max_step);
  EXPECT_EQ(normal.rest_stride, defaults.rest_stride);
  EXPECT_EQ(normal.mid_step_rest, defaults.mid_step_rest);
  EXPECT_EQ(normal.rest_sweeps, defaults.rest_sweeps);
  EXPECT_EQ(normal.soft_rest_substeps, defaults.soft_rest_substeps);
  EXPECT_EQ(normal.soft_rest_hertz, defaults.soft_rest_hertz);
  EXPECT_EQ(normal.soft_rest_island, defaults.soft_rest_island);
  EXPECT_EQ(normal.sleep.bands, defaults.sleep.bands);
  EXPECT_EQ(normal.min_step, defaults.min_step);
  EXPECT_EQ(normal.max_bisections, defaults.max_bisections);
  EXPECT_EQ(normal.max_resolution_passes, defaults.max_resolution_passes);
  EXPECT_EQ(normal.resolved_gap_fraction, defaults.resolved_gap_fraction);
  EXPECT_EQ(normal.narrow_phase.relative_accuracy, defaults.narrow_phase.relative_accuracy);
  EXPECT_EQ(normal.narrow_phase.seed_iterations, defaults.narrow_phase.seed_iterations);
  EXPECT_EQ(normal.narrow_phase.max_depth, defaults.narrow_phase.max_depth);
  EXPECT_EQ(normal.narrow_phase.max_cells, defaults.narrow_phase.max_cells);
}

// "Finer" for each knob: a shorter step, shorter rest steps and tolerances, more iterations,
// depth and passes.
TEST(Accuracy, PresetsAreOrderedOnEveryKnob) {
  const Accuracy draft = *accuracy_preset("draft");
  const Accuracy normal = *accuracy_preset("normal");
  const Accuracy precise = *accuracy_preset("precise");
  const std::set<std::string> smaller_is_finer = {"max_step", "rest_stride", "toi_tolerance",
                                                  "newton_tolerance", "contact_threshold"};
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    const double d = knob.get(draft), n = knob.get(normal), p = knob.get(precise);
    // Not finer or coarser: which resting solve (accuracy.h). Only normal rests softly.
    if (knob.key == "soft_rest") {
      EXPECT_EQ(d, 0.0);
      EXPECT_GT(n, 0.0);
      EXPECT_EQ(p, 0.0);
      continue;
    }
    if (smaller_is_finer.count(std::string(knob.key)) != 0) {
      EXPECT_GE(d, n) << knob.key;
      EXPECT_GE(n, p) << knob.key;
    } else {
      EXPECT_LE(d, n) << knob.key;
      EXPECT_LE(n, p) << knob.key;
    }
    EXPECT_TRUE(knob.valid(d) && knob.valid(n) && knob.valid(p)) << knob.key;
  }
  EXPECT_FALSE(accuracy_preset("fast").has_value());
  EXPECT_EQ(accuracy_preset_names(), (std::vector<std::string>{"draft", "normal", "precise"}));
}

TEST(Accuracy, EveryKnobReachesItsWorldSetting) {
  Accuracy a;
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    // A value inside the range and unlike the default: the upper end, or half of it.
    const double value = knob.integer ? knob.hi : 0.5 * knob.hi;
    knob.set(a, value);
    EXPECT_EQ(knob.get(a), value) << knob.key;
    EXPECT_EQ(find_accuracy_knob(knob.key), &knob);
  }
  a.toi_tolerance = 1e-6;
  const WorldSettings w = with_accuracy(WorldSettings{}, a);
  EXPECT_EQ(w.max_step, 0.5);
  EXPECT_EQ(w.min_step, 1e-6);
  EXPECT_EQ(w.max_bisections, 200);
  EXPECT_EQ(w.narrow_phase.relative_accuracy, 0.5e-3);
  EXPECT_EQ(w.narrow_phase.seed_iterations, 1000);
  EXPECT_EQ(w.narrow_phase.max_depth, 60);
  EXPECT_EQ(w.max_resolution_passes, 100000);
  EXPECT_EQ(w.resolved_gap_fraction, 0.25);
  EXPECT_EQ(w.soft_rest_substeps, 64);
  EXPECT_EQ(w.soft_rest_hertz, 5e5);
  EXPECT_EQ(w.soft_rest_island, 1000000);
  EXPECT_EQ(find_accuracy_knob("max_stp"), nullptr);
  // The rest of the settings are the caller's.
  WorldSettings base;
  base.gravity = Vec2(1.0, 2.0);
  base.friction_gain = 7.0;
  const WorldSettings kept = with_accuracy(base, Accuracy{});
  EXPECT_EQ(kept.gravity, base.gravity);
  EXPECT_EQ(kept.friction_gain, 7.0);
}

TEST(Accuracy, OutOfRangeKnobsAreRefusedByName) {
  auto message = [](const Accuracy& a) {
    try {
      (void)with_accuracy(WorldSettings{}, a);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  Accuracy a;
  a.max_step = 0.0;
  EXPECT_EQ(message(a), "accuracy: max_step must be a number in (0, 1] (s), got 0");
  a = Accuracy{};
  a.seed_depth = 61;
  EXPECT_EQ(message(a), "accuracy: seed_depth must be an integer in [8, 60], got 61");
  a = Accuracy{};
  a.newton_tolerance = 1e-2;
  EXPECT_EQ(message(a), "accuracy: newton_tolerance must be a number in [1e-15, 0.001], got 0.01");
  a = Accuracy{};
  a.toi_tolerance = 2e-3;
  EXPECT_EQ(message(a), "accuracy: toi_tolerance (0.002 s) must not exceed max_step (0.001 s)");
  const AccuracyKnob& passes = *find_accuracy_knob("contact_passes");
  EXPECT_FALSE(passes.valid(2.5));
  EXPECT_FALSE(passes.valid(0));
  EXPECT_FALSE(passes.valid(std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(passes.valid(1));
}

}  // namespace
}  // namespace rugosim
