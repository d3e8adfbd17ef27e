// The validation scenes in Box2D at three settings, measured with rugosim's closed forms
// (accuracy_metrics.h), and the CSV and Markdown the accuracy study writes of them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "accuracy_metrics.h"
#include "box2d_scene.h"

namespace rugosim::bench {

// A Box2D setting of the comparison: a label for the tables and the options (length_scale is
// chosen per scene, suggested_length_scale()).
struct Box2dSetting {
  std::string label;
  Box2dSceneOptions options;
};

// (a) Box2D's recommended 60 Hz with 8/3 iterations, disks as circles; (b) 240 Hz with 20/10
// iterations; (c) as (a) with disks as 32-gons, for scenes with a disk.
std::vector<Box2dSetting> box2d_validation_settings();

struct Box2dClosedForm {
  std::string scene;  // as given, e.g. "validation_sliding_disk"
  std::string setting;
  Box2dSceneOptions options;                    // as run, with the scene's length_scale
  double wall_s = 0.0;                          // s, Box2D's stepping (best of the repeats)
  std::optional<study::ClosedFormError> error;  // nullopt when the scene has no closed form
  std::string unsupported;  // non-empty when Box2D could not build the scene: why
};

// Every scene of `name_and_path` (name as closed_form_error knows it, scene file) at every
// setting of box2d_validation_settings(), each timed `repeats` times. A scene the translation
// does not support gives one entry saying why; a scene that does not load throws
// std::runtime_error.
std::vector<Box2dClosedForm> run_box2d_validation(
    const std::vector<std::pair<std::string, std::string>>& name_and_path, int repeats);

// One row per scene, setting and compared quantity: scene, setting, hz, iterations, circles,
// length_scale, wall_s, quantity, relative error.
void write_box2d_csv(const std::filesystem::path& path,
                     const std::vector<Box2dClosedForm>& results);

// A table of the relative errors, one row per scene and quantity and one column per setting,
// the wall times, and what the translation does and cannot express.
void write_box2d_markdown(const std::filesystem::path& path,
                          const std::vector<Box2dClosedForm>& results);

}  // namespace rugosim::bench
