// The simulation options of simulate, render and snapshot: --accuracy PRESET and one option per
// knob (--max-step, --toi-tolerance, ...; engine/dynamics/accuracy.h), each checked against the
// knob's range by CLI11 (exit 2 with the expected range), and --threads.
#pragma once

#include <CLI/CLI.hpp>

#include "render/app/scene_input.h"

namespace rugosim::app {

// Adds the options to `command`; what the user gives ends up in `out`.
void add_accuracy_options(CLI::App& command, AccuracyOverride& out);

// Adds --threads N to `command`: threads of collision detection, 1 to World::kMaxThreads.
// `threads` holds the default on entry: the CPUs this process may run on (available_cpus()).
// Threads never change a result, so they are an option of the run, not a scene key.
void add_threads_option(CLI::App& command, int& threads);

}  // namespace rugosim::app
