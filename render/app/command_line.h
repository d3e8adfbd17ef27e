// The rugosim command line (INTERFACE.md, "Command line"): every command and option, and what
// the user gave, without running anything. main() parses with it and runs the chosen command;
// the tests and the command-line fuzz target (tests/fuzz) walk and parse the same options.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/app/commands.h"

namespace rugosim::app {

struct CommandLine {
  CLI::App app{"rugosim: simulate and render 2D rigid bodies with rough B-spline boundaries",
               "rugosim"};
  CLI::App* validate = nullptr;
  CLI::App* info = nullptr;
  CLI::App* simulate = nullptr;
  CLI::App* render = nullptr;
  CLI::App* snapshot = nullptr;
  CLI::App* plot = nullptr;
  CLI::App* join = nullptr;
  CLI::App* plan = nullptr;
  CLI::App* plan_render = nullptr;
  CLI::App* sweep = nullptr;

  // What was given; complete only after finish_parse().
  std::string scene;  // validate and info
  bool json = false;  // info --json
  SimulateOptions sim;
  RenderOptions render_options;
  SnapshotOptions snap;
  PlotOptions plot_options;
  JoinOptions join_options;
  PlanOptions plan_options;
  SweepOptions sweep_options;
  std::optional<double> plan_fps;  // set into plan_options by finish_parse
  int plan_crf = 18;

  // Raw values of options whose absence means "the scene's value" (see finish_parse).
  double duration = 0.0, fps = 0.0;
  double render_fps = 0.0, render_duration = 0.0, render_roughness_scale = 1.0;
  std::vector<std::string> overlays;
  int gl_threads = 0;
  bool no_contacts = false;
};

// All commands and options; --threads defaults to `cpus` (available_cpus() in the program).
std::unique_ptr<CommandLine> make_command_line(int cpus);

// After app.parse(): moves the options given into the command's options (an option not given
// leaves the scene's value in force).
void finish_parse(CommandLine& c);

// When `word` (the first argument) is not an option and names no command: the error for it,
// with the nearest command when it is close enough to be a typo (closest_match, as for
// misspelt scene keys), e.g. `unknown command "simulte"; did you mean "simulate"?`. Empty when
// `word` is an option or a command.
std::string unknown_command_error(const CommandLine& c, const std::string& word);

}  // namespace rugosim::app
