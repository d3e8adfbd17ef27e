// The accuracy study's settings part (bench/accuracy_study.cpp): every built-in scene at each
// setting of the knobs, what it keeps of each run, and what it writes of them: accuracy.csv,
// accuracy.md (every setting, the presets scene by scene against the method's limit, the closed
// forms with their floors) and pareto.png (error against wall time, the Pareto front, the peer
// engine's points).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "accuracy_metrics.h"
#include "engine/dynamics/accuracy.h"
#include "engine/scene/scene.h"

namespace rugosim::study {

struct Setting {
  std::string label;  // "draft", "max_step=0.004", ...
  std::string knob;   // "preset" or the knob's key
  double value = 0.0;
  Accuracy accuracy;
};

// The reference is checked against a run at this share of its step (the per-scene table's last
// column).
inline constexpr double kReferenceCheckShare = 0.25;

// The tightest settings of the study: the figure scenes' reference.
Accuracy reference_accuracy();

struct SceneFile {
  std::string name;
  std::string path;
  Scene scene;
  bool validation = false;
  Run reference;
  // The reference's own RMS distance from a run at a quarter of its step, in body radii. A
  // preset's error at or below it is not a measured difference.
  double reference_spread = 0.0;
  std::optional<ClosedFormError> reference_closed;  // validation scenes: the model's floor
};

struct Row {
  std::string scene;
  bool validation = false;
  double wall_s = 0.0;
  double error = 0.0;
  double limit_error = 0.0;  // RMS distance from the reference, in body radii (every scene)
  std::string measure;
  std::vector<std::pair<std::string, double>> parts;  // validation scenes: what was compared
  StepStats stats;
};

struct Summary {
  const Setting* setting = nullptr;
  std::vector<Row> rows;
  double wall_s = 0.0;            // all scenes
  double validation_error = 0.0;  // geometric mean over the validation scenes
  double figure_error = 0.0;      // geometric mean over the figure scenes
  double worst_validation = 0.0;
  std::uint64_t crossings = 0;
  std::uint64_t fallbacks = 0;
  bool front_validation = false;  // on the Pareto front of (wall, validation error)
  bool front_figure = false;
};

// Another engine's setting as a point of the validation panel (Box2D: box2d_validation.h): its
// validation error over the same scenes and its total wall time.
struct PeerPoint {
  std::string label;
  double wall_s = 0.0;
  double validation_error = 0.0;
};

// Errors below this count as this in the geometric means: the rounding of single precision
// (Box2D computes in float), below which a closed form here tells nothing more. Without it, a
// scene that one engine answers to double rounding (two disks colliding: 1e-16) and the other
// to float rounding (1e-8) would weigh a factor of 10^8 in the mean.
inline constexpr double kErrorResolution = 1e-7;
// Of the values, each at least kErrorResolution.
double geometric_mean(const std::vector<double>& values);

void write_settings_csv(const std::filesystem::path& path, const std::vector<Summary>& all);
void write_settings_markdown(const std::filesystem::path& path, const std::vector<Summary>& all,
                             const std::vector<SceneFile>& scenes, int repeats);
// Two panels, validation error and figure error against the total wall time, log-log; the
// presets labelled, the Pareto front as a line, the peers' points on the validation panel.
void write_pareto_plot(const std::filesystem::path& path, const std::vector<Summary>& all,
                       const std::vector<PeerPoint>& peers);

}  // namespace rugosim::study
