// What the accuracy study measures (bench/accuracy_study.cpp): a scene simulated frame by frame
// with given knobs, the error of a validation scene against its closed form, and the deviation
// of a run from a reference run of the same scene.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/step_stats.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"

namespace rugosim::study {

// A scene run: the states of its movable bodies at every frame time k / fps, 0 <= k / fps <=
// duration, as `rugosim simulate` writes them.
struct Run {
  std::vector<std::size_t> movers;             // body indices, in order
  std::vector<std::vector<BodyState>> frames;  // frames[k][m]: mover m at frame k
  double fps = 30.0;                           // frames per second
  StepStats stats;                             // of the World at the end
  double wall_s = 0.0;                         // s, the simulation alone (best of the runs)
  std::shared_ptr<const World> world;          // the World at the end (bodies, materials)
};

// Simulates `scene` with `accuracy` (replacing the scene's own) `repeats` times and keeps the
// fastest run's time; the runs are bit-identical, so any of them gives the states.
Run run_scene(const Scene& scene, const std::string& file, const Accuracy& accuracy, int repeats);

// The closed form a validation scene checks and the run's relative error against it, or
// nullopt for a scene without one. `what` says what was compared.
struct ClosedFormError {
  double error = 0.0;  // dimensionless: the largest of the parts
  std::string what;
  // The quantities compared, each with its relative error (e.g. "rolling speed").
  std::vector<std::pair<std::string, double>> parts;
};
std::optional<ClosedFormError> closed_form_error(const std::string& name, const Scene& scene,
                                                 const Run& run);

// RMS over frames and movable bodies of |x − x_ref| / (the body's bounding radius): how far a
// run's bodies are from the reference run's, in body sizes.
double trajectory_error(const Run& run, const Run& reference);

}  // namespace rugosim::study
