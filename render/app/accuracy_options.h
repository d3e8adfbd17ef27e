// The accuracy options of simulate, render and snapshot: --accuracy PRESET and one option per
// knob (--max-step, --toi-tolerance, ...; engine/dynamics/accuracy.h), each checked against the
// knob's range by CLI11 (exit 2 with the expected range).
#pragma once

#include <CLI/CLI.hpp>

#include "render/app/scene_input.h"

namespace rugosim::app {

// Adds the options to `command`; what the user gives ends up in `out`.
void add_accuracy_options(CLI::App& command, AccuracyOverride& out);

}  // namespace rugosim::app
