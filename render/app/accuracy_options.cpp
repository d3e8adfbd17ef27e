#include "render/app/accuracy_options.h"

#include <algorithm>
#include <string>

#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/world.h"
#include "render/app/number_option.h"

namespace rugosim::app {

void add_accuracy_options(CLI::App& command, AccuracyOverride& out) {
  command
      .add_option_function<std::string>(
          "--accuracy", [&out](const std::string& preset) { out.preset = preset; },
          "draft, normal or precise: replaces the scene's accuracy (preset and knobs)")
      ->check(CLI::IsMember(accuracy_preset_names()))
      ->type_name("PRESET");
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    std::string name = "--" + std::string(knob.key);
    std::replace(name.begin(), name.end(), '_', '-');
    const std::string key(knob.key);
    const CLI::Validator in_range(
        [knob](std::string& text) -> std::string {
          const std::optional<double> value = parse_number(text, knob.integer);
          if (value && knob.valid(*value)) return {};
          return "expected " + knob.expectation() + ", got \"" + text + "\"";
        },
        knob.expectation(), kNumberValidator);
    command
        .add_option_function<double>(
            name, [&out, key](const double& value) { out.knobs[key] = value; },
            std::string(knob.help) + (knob.unit.empty() ? "" : ", " + std::string(knob.unit)) +
                " (overrides the preset)")
        ->check(in_range)
        ->type_name(knob.integer ? "N" : "X");
  }
}

void add_threads_option(CLI::App& command, int& threads) {
  command
      .add_option("--threads", threads,
                  "threads for collision detection (default: the CPUs this process may use, " +
                      std::to_string(threads) + " here); results do not depend on it")
      ->check(number_in({1, false, World::kMaxThreads, false, true, ""}))
      ->type_name("N");
}

}  // namespace rugosim::app
