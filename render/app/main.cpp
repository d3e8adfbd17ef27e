// The rugosim command line (INTERFACE.md, "Command line"): validate, info, simulate and plot so
// far; render and snapshot arrive with their layers.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "engine/core/version.h"
#include "render/app/commands.h"
#include "render/app/scene_input.h"

int main(int argc, char** argv) {
  using namespace rugosim::app;
  CLI::App app{"rugosim: simulate and render 2D rigid bodies with rough B-spline boundaries",
               "rugosim"};
  app.set_version_flag("--version", std::string("rugosim ") + rugosim::kVersion);
  app.footer(
      "Exit codes: 0 success, 1 runtime failure, 2 bad usage or invalid scene, 130 interrupted.\n"
      "Run 'rugosim COMMAND --help' for a command's options and examples.");
  app.require_subcommand(0, 1);

  std::string scene;
  CLI::App* validate = app.add_subcommand("validate", "check a scene file, reporting every error");
  validate->add_option("SCENE", scene, "scene file (JSON)")->required();
  validate->footer("Example: rugosim validate scenes/figure12a.json");

  bool json = false;
  CLI::App* info = app.add_subcommand(
      "info", "per body: segments, area, mass, centroid, inertia, range of lambda, tree depth");
  info->add_option("SCENE", scene, "scene file (JSON)")->required();
  info->add_flag("--json", json, "print JSON: {\"bodies\": [{\"name\", \"segments\", ...}]}");
  info->footer("Example: rugosim info scenes/figure09_constant.json --json");

  SimulateOptions sim;
  double duration = 0.0, fps = 0.0;
  std::string accuracy;
  CLI::App* simulate = app.add_subcommand("simulate", "simulate a scene and write telemetry");
  simulate->add_option("SCENE", sim.scene_path, "scene file (JSON)")->required();
  simulate->add_option("--duration", duration, "simulated time, s (default: world.duration)")
      ->check(CLI::PositiveNumber);
  simulate->add_option("--fps", fps, "trajectory frames per second (default: render.fps)")
      ->check(CLI::PositiveNumber);
  simulate->add_option("--accuracy", accuracy, "draft, normal or precise (default: the scene's)")
      ->check(CLI::IsMember({"draft", "normal", "precise"}));
  simulate->add_option("--trajectory", sim.trajectory_path, "write trajectory.csv here");
  simulate->add_option("--events", sim.events_path, "write events.csv (one row per impulse)");
  simulate->add_option("--stats", sim.stats_path, "write stats.json (step statistics)");
  simulate->footer(
      "Example: rugosim simulate scenes/figure12a.json --trajectory out/traj.csv "
      "--events out/events.csv --stats out/stats.json\n"
      "Files are written atomically: on an error none is created or truncated; on Ctrl-C the "
      "frames simulated so far are written and the exit code is 130.");

  PlotOptions plot_options;
  bool no_contacts = false;
  CLI::App* plot = app.add_subcommand(
      "plot", "draw friction per collision event and velocity over time as PNG (gnuplot)");
  plot->add_option("--events", plot_options.events_path,
                   "events.csv: draw DIR/friction.png, mu of each collision over time")
      ->type_name("FILE.csv");
  plot->add_option("--trajectory", plot_options.trajectory_path,
                   "trajectory.csv: draw DIR/velocity.png, speed |v| and vx over time")
      ->type_name("FILE.csv");
  plot->add_option("-o,--output", plot_options.output_dir, "output folder (created if missing)")
      ->required()
      ->type_name("DIR");
  plot->add_option("--bodies", plot_options.bodies,
                   "bodies of the velocity plot, NAME,NAME... (default: all; quote a name that "
                   "holds a comma as in CSV)")
      ->type_name("NAME,NAME...");
  plot->add_flag("--no-contacts", no_contacts,
                 "leave out the resting-contact micro-collisions (kind \"contact\")");
  plot->footer(
      "Example: rugosim plot --events out/events.csv --trajectory out/traj.csv -o out/plots "
      "--bodies 'pebble,\"disk, small\"'\n"
      "At least one of --events and --trajectory is needed. Requires gnuplot on PATH (Debian: "
      "gnuplot-nox). PNGs are written atomically; a bad CSV leaves none (exit 2).");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 returns 0 for --help/--version; usage errors become exit code 2.
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  if (validate->parsed()) return run_validate(scene);
  if (info->parsed()) return run_info(scene, json);
  if (simulate->parsed()) {
    if (simulate->count("--duration") > 0) sim.duration = duration;
    if (simulate->count("--fps") > 0) sim.fps = fps;
    if (simulate->count("--accuracy") > 0) sim.accuracy = accuracy;
    return run_simulate(sim);
  }
  if (plot->parsed()) {
    plot_options.contacts = !no_contacts;
    return run_plot(plot_options);
  }
  fmt::print("{}", app.help());
  return kExitOk;
}
