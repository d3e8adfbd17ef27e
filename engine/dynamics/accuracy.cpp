#include "engine/dynamics/accuracy.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/core/number_text.h"

namespace rugosim {

void AccuracyKnob::set(Accuracy& a, double value) const {
  if (integer) {
    a.*count = static_cast<int>(value);
  } else {
    a.*real = value;
  }
}

bool AccuracyKnob::valid(double value) const {
  if (!std::isfinite(value)) return false;
  if (integer && value != std::floor(value)) return false;
  return (lo_open ? value > lo : value >= lo) && value <= hi;
}

std::string AccuracyKnob::expectation() const {
  std::ostringstream text;
  text << (integer ? "an integer in " : "a number in ") << (lo_open ? "(" : "[") << lo << ", " << hi
       << "]";
  if (!unit.empty()) text << " (" << unit << ")";
  return text.str();
}

const std::vector<AccuracyKnob>& accuracy_knobs() {
  static const std::vector<AccuracyKnob> knobs = {
      {"max_step", "s", "the longest internal step", false, 0.0, true, 1.0, &Accuracy::max_step,
       nullptr},
      {"rest_stride", "", "a step near contacts that close gently may last this many max_steps",
       true, 1, false, 1024, nullptr, &Accuracy::rest_stride},
      {"mid_step_rest", "",
       "1: slow contacts get their impulses at each step's middle; 0: micro-collisions only", true,
       0, false, 1, nullptr, &Accuracy::mid_step_rest},
      {"converging_contacts", "",
       "1: contact rules that do not depend on the step (impacts located in time, rest by speed, "
       "deep contacts lifted); 0: the paper's rules at each step's end",
       true, 0, false, 1, nullptr, &Accuracy::converging_contacts},
      {"rest_sweeps", "", "Gauss-Seidel sweeps of each mid-step solve at most", true, 1, false,
       100000, nullptr, &Accuracy::rest_sweeps},
      {"soft_rest", "",
       "substeps of the soft resting solve with warm starts (piles rest and sleep); 0: the "
       "mid-step solve",
       true, 0, false, 64, nullptr, &Accuracy::soft_rest},
      {"soft_rest_hertz", "Hz", "the soft resting solve's contact spring", false, 0.0, true, 1e6,
       &Accuracy::soft_rest_hertz, nullptr},
      {"soft_rest_island", "",
       "the soft resting solve takes islands of at least this many moving bodies in contact; "
       "smaller ones keep the mid-step solve",
       true, 1, false, 1000000, nullptr, &Accuracy::soft_rest_island},
      {"toi_tolerance", "s", "time-of-impact bisection stops at this step", false, 0.0, true, 1.0,
       &Accuracy::toi_tolerance, nullptr},
      {"max_bisections", "", "bisections of one step at most", true, 1, false, 200, nullptr,
       &Accuracy::max_bisections},
      {"newton_tolerance", "", "nearest-point accuracy, relative to the segments' size", false,
       1e-15, false, 1e-3, &Accuracy::newton_tolerance, nullptr},
      {"newton_iterations", "", "Newton steps from each seed", true, 1, false, 1000, nullptr,
       &Accuracy::newton_iterations},
      {"seed_depth", "", "subdivision depth of the search for seeds", true, 8, false, 60, nullptr,
       &Accuracy::seed_depth},
      {"contact_passes", "", "passes of collisions and micro-collisions per state", true, 1, false,
       100000, nullptr, &Accuracy::contact_passes},
      {"contact_threshold", "", "share of its gap a contact may close in a step unresolved", false,
       0.0, false, 0.5, &Accuracy::contact_threshold, nullptr},
  };
  return knobs;
}

const AccuracyKnob* find_accuracy_knob(std::string_view key) {
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    if (knob.key == key) return &knob;
  }
  return nullptr;
}

const std::vector<std::string>& accuracy_preset_names() {
  static const std::vector<std::string> names = {"draft", "normal", "precise"};
  return names;
}

// The values come from bench/accuracy_study.cpp (docs/accuracy/): what each knob buys, and what
// it costs, on the validation and figure scenes. Every preset rests contacts at mid-step
// (docs/research/resting-contact.md §8.7). draft steps 2 ms: at 4 ms figure12a's rocks kept
// rocking at a few cm/s and never slept, which cost more than the shorter step. precise takes
// no rest steps and a resolved-contact threshold of 1e-5: at 1e-3 (a share of the gap closed
// per step, so a threshold that tightens as the step grows) its figure06_type3_type4 ended
// 3.4 mm from the reference, at 1e-5 0.04 mm. precise takes converging_contacts 1: with it,
// precise is 1e-5 to 5e-4 body radii from the method's limit on every non-chaotic scene, where
// under the step-end rules it was as far as normal (up to 0.04); draft and normal keep the
// step-end rules until locating impacts costs a pile less (pile_200 at normal takes 3.5× its
// time with them, the 50-body pile 1.5×).
std::optional<Accuracy> accuracy_preset(std::string_view name) {
  if (name == "normal") return Accuracy{};
  if (name == "draft") {
    return Accuracy{.max_step = 2e-3,
                    .rest_sweeps = 16,
                    .soft_rest = 0,
                    .toi_tolerance = 1e-7,
                    .max_bisections = 30,
                    .newton_tolerance = 1e-9,
                    .newton_iterations = 16,
                    .seed_depth = 24,
                    .contact_passes = 32};
  }
  if (name == "precise") {
    return Accuracy{.max_step = 2.5e-4,
                    .rest_stride = 1,
                    .converging_contacts = 1,
                    .soft_rest = 0,
                    .toi_tolerance = 1e-10,
                    .max_bisections = 80,
                    .newton_tolerance = 1e-13,
                    .newton_iterations = 60,
                    .seed_depth = 52,
                    .contact_passes = 128,
                    .contact_threshold = 1e-5};
  }
  return std::nullopt;
}

WorldSettings with_accuracy(WorldSettings base, const Accuracy& accuracy) {
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    const double value = knob.get(accuracy);
    if (!knob.valid(value)) {
      throw std::invalid_argument("accuracy: " + std::string(knob.key) + " must be " +
                                  knob.expectation() + ", got " + number_text(value));
    }
  }
  if (accuracy.toi_tolerance > accuracy.max_step) {
    throw std::invalid_argument("accuracy: toi_tolerance (" + number_text(accuracy.toi_tolerance) +
                                " s) must not exceed max_step (" + number_text(accuracy.max_step) +
                                " s)");
  }
  base.max_step = accuracy.max_step;
  base.rest_stride = accuracy.rest_stride;
  base.mid_step_rest = accuracy.mid_step_rest != 0;
  base.converging_contacts = accuracy.converging_contacts != 0;
  base.rest_sweeps = accuracy.rest_sweeps;
  base.soft_rest_substeps = accuracy.soft_rest;
  base.soft_rest_hertz = accuracy.soft_rest_hertz;
  base.soft_rest_island = accuracy.soft_rest_island;
  base.min_step = accuracy.toi_tolerance;
  base.max_bisections = accuracy.max_bisections;
  base.max_resolution_passes = accuracy.contact_passes;
  base.resolved_gap_fraction = accuracy.contact_threshold;
  base.narrow_phase.relative_accuracy = accuracy.newton_tolerance;
  base.narrow_phase.seed_iterations = accuracy.newton_iterations;
  base.narrow_phase.max_depth = accuracy.seed_depth;
  return base;
}

}  // namespace rugosim
