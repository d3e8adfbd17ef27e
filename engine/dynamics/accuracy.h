// The speed/accuracy trade (INTERFACE.md: `world.accuracy`; README, "Accuracy"): the knobs
// that decide how closely the World follows the paper's model, and the three presets that set
// them together. bench/accuracy_study.cpp measures every preset and every knob against closed
// forms and against reference runs, and docs/accuracy/ holds what it found.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/dynamics/world.h"

namespace rugosim {

struct Accuracy {
  // s: the longest internal step near a contact that closes fast. Free flight is exact, so this
  // sets how often contacts are looked for, how deep into its band a body gets before it is
  // found, and how often resting bodies get their micro-collisions.
  double max_step = 1e-3;
  // How many max_steps a step near contact may last while every pair that can meet in it
  // closes gently (WorldSettings::rest_stride): rest steps. 16 in `draft` and `normal`: with
  // mid-step rest a resting body does not creep, however long the step (docs/accuracy; under
  // micro-collisions alone it creeps ½·g·sinθ·h per step of length h). 1 in `precise`, whose
  // steps follow max_step everywhere.
  int rest_stride = 16;
  // 1: slow contacts get their impulses at the start of each step, on the velocities at its
  // middle (WorldSettings::mid_step_rest, mid_step_rest.h), so a resting body neither creeps
  // nor slides further than friction lets it, whatever the step; 0: the paper's
  // micro-collisions alone. 1 in every preset (docs/research/resting-contact.md §8.7).
  int mid_step_rest = 1;
  // 1: contact rules that do not depend on the step (WorldSettings::converging_contacts):
  // impacts answered where they happen, located by bisection, slow approaches told from impacts
  // by speed, deep contacts lifted at a rate of their band's; 0: the paper's rules at each
  // step's end. 1 is what the convergence study converges with (docs/accuracy/convergence.md).
  int converging_contacts = 0;
  // Gauss-Seidel sweeps of each mid-step solve at most (WorldSettings::rest_sweeps). Where they
  // run out, micro-collisions answer what the solve left: 16 in draft makes figure12a 1.25×
  // cheaper.
  int rest_sweeps = 64;
  // Substeps of the soft resting solve (soft_rest.h; WorldSettings::soft_rest_substeps) in
  // place of the mid-step solve, 0 for none: Box2D v3's soft contacts with warm starts, in n
  // substeps of each rest step, under which a pile comes to rest within a fifth of a band and
  // sleeps (its bodies are judged by the sleep test's stricter soft windows, sleep_tracker.h).
  // It replaces the mid-step solve, so with mid_step_rest 0 it does nothing. 8 in `normal` (a
  // 200-body pile asleep by 4 s within a band, where the mid-step solve lets it creep 15 bands;
  // the 1,000-body pile asleep by 6.5 s once the springs are stiffened by their load:
  // docs/research/resting-contact.md §8.18–8.20). 0 in `draft`, whose 2 ms steps put the soft
  // springs at the edge of their substeps (the 200-body pile never slept, 6× slower), and in
  // `precise`, whose rest is the mid-step solve's, exact where it converges. Not a finer or
  // coarser setting but another resting model.
  int soft_rest = 8;
  // Hz: the soft contacts' spring (SoftRestSettings::hertz).
  double soft_rest_hertz = 60.0;
  // With soft_rest: the smallest island (moving bodies linked by contacts) it takes; smaller
  // islands, and islands with a contact band too narrow for the spring (soft_rest_min_band),
  // keep the mid-step solve (WorldSettings::soft_rest_island). 2: a body alone on a slope rests
  // exactly, where the springs would let it creep 5e-7 m/s.
  int soft_rest_island = 2;
  // s: a step whose end crosses is bisected back towards the first contact until it is this
  // short (the time-of-impact tolerance; World's min_step).
  double toi_tolerance = 1e-9;
  // Bisections of one step at most.
  int max_bisections = 60;
  // Dimensionless: slack of the nearest-point certificate, as a fraction of the segments' size
  // (NarrowPhaseSettings::relative_accuracy).
  double newton_tolerance = 1e-12;
  // Newton steps of each descent from a seed.
  int newton_iterations = 40;
  // Halvings of the parameter intervals when seeds are searched by subdivision.
  int seed_depth = 48;
  // Passes over the contacts of a state (collisions and micro-collisions) before the
  // rigid-cluster fallback.
  int contact_passes = 64;
  // Dimensionless: a contact needs an impulse only while it would close more than this
  // fraction of its gap within a step.
  double contact_threshold = 1e-3;

  friend bool operator==(const Accuracy&, const Accuracy&) = default;
};

// One knob: its scene key (also the CLI option, with '-' for '_'), unit and valid range.
struct AccuracyKnob {
  std::string_view key;
  std::string_view unit;  // "s", or "" for dimensionless and counts
  std::string_view help;  // what it sets, in a few words
  bool integer = false;
  double lo = 0.0;  // inclusive unless lo_open
  bool lo_open = false;
  double hi = 0.0;  // inclusive
  double Accuracy::*real = nullptr;
  int Accuracy::*count = nullptr;

  double get(const Accuracy& a) const { return integer ? a.*count : a.*real; }
  void set(Accuracy& a, double value) const;
  bool valid(double value) const;
  std::string expectation() const;  // e.g. "a number in (0, 1] (s)"
};

// Every knob, in the order above.
const std::vector<AccuracyKnob>& accuracy_knobs();
const AccuracyKnob* find_accuracy_knob(std::string_view key);

// The presets' names, fastest first: "draft", "normal", "precise".
const std::vector<std::string>& accuracy_preset_names();
// The knobs of a preset, or nullopt for an unknown name. "normal" is Accuracy{}.
std::optional<Accuracy> accuracy_preset(std::string_view name);

// The World settings these knobs give, on top of `base` (gravity, friction, sleep, ...).
// Throws std::invalid_argument when a knob is out of its range or the time-of-impact
// tolerance exceeds the longest step.
WorldSettings with_accuracy(WorldSettings base, const Accuracy& accuracy);

}  // namespace rugosim
