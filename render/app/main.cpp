// The rugosim command line (INTERFACE.md, "Command line"): validate, info, simulate, render,
// snapshot and plot.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "engine/core/thread_pool.h"
#include "engine/core/version.h"
#include "render/app/accuracy_options.h"
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
  CLI::App* simulate = app.add_subcommand("simulate", "simulate a scene and write telemetry");
  simulate->add_option("SCENE", sim.scene_path, "scene file (JSON)")->required();
  simulate->add_option("--duration", duration, "simulated time, s (default: world.duration)")
      ->check(CLI::PositiveNumber);
  simulate->add_option("--fps", fps, "trajectory frames per second (default: render.fps)")
      ->check(CLI::PositiveNumber);
  add_accuracy_options(*simulate, sim.accuracy);
  const int cpus = rugosim::available_cpus();
  sim.threads = cpus;
  add_threads_option(*simulate, sim.threads);
  simulate->add_option("--trajectory", sim.trajectory_path, "write trajectory.csv here");
  simulate->add_option("--events", sim.events_path, "write events.csv (one row per impulse)");
  simulate->add_option("--stats", sim.stats_path, "write stats.json (step statistics)");
  simulate->footer(
      "Example: rugosim simulate scenes/figure12a.json --trajectory out/traj.csv "
      "--events out/events.csv --stats out/stats.json\n"
      "Files are written atomically: on an error none is created or truncated; on Ctrl-C the "
      "frames simulated so far are written and the exit code is 130.");

  RenderOptions render_options;
  double render_fps = 0.0, render_duration = 0.0;
  std::vector<std::string> overlays;
  CLI::App* render = app.add_subcommand(
      "render", "render a scene off-screen to an MP4 clip, a PNG sequence or a film strip");
  render->add_option("SCENE", render_options.scene_path, "scene file (JSON)")->required();
  render
      ->add_option("-o,--output", render_options.output,
                   "clip.mp4, a PNG pattern like out/f_%04d.png, or with --strip one PNG")
      ->required()
      ->type_name("OUT");
  render
      ->add_option("--format", render_options.format,
                   "mp4 or png (default: from OUT: .mp4, or a pattern with %d)")
      ->check(CLI::IsMember({"mp4", "png"}));
  render
      ->add_option("--frames", render_options.frames,
                   "frames A:B, inclusive (default: 0 to duration × fps)")
      ->type_name("A:B");
  render->add_option("--size", render_options.size, "frame size (default: render.size)")
      ->type_name("WxH");
  render->add_option("--fps", render_fps, "frames per second (default: render.fps)")
      ->check(CLI::PositiveNumber);
  render->add_option("--duration", render_duration, "simulated time, s (default: world.duration)")
      ->check(CLI::PositiveNumber);
  add_accuracy_options(*render, render_options.accuracy);
  render_options.threads = cpus;
  add_threads_option(*render, render_options.threads);
  render->add_option("--crf", render_options.crf, "MP4: x264 constant rate factor 0..51")
      ->capture_default_str();
  render->add_option("--preset", render_options.preset, "MP4: x264 preset")->capture_default_str();
  render->add_flag("-y", render_options.overwrite, "overwrite OUT if it exists");
  render->add_option("--backend", render_options.backend, "OpenGL backend: osmesa or egl")
      ->capture_default_str();
  render
      ->add_option("--aa", render_options.anti_aliasing,
                   "anti-aliasing: shader (edge coverage in the shaders), msaa (4x) or none")
      ->capture_default_str();
  render
      ->add_option("--overlay", overlays,
                   "overlays, replacing render.overlays: rugosity, contacts, velocity (comma "
                   "separated; \"none\" for none)")
      ->delimiter(',')
      ->type_name("LIST");
  render
      ->add_option("--strip", render_options.strip,
                   "write one PNG of N frames spread over the clip, side by side")
      ->check(CLI::PositiveNumber)
      ->type_name("N");
  int gl_threads = 0;
  render
      ->add_option("--gl-threads", gl_threads,
                   "llvmpipe rasteriser threads (LP_NUM_THREADS); default 0: the render thread "
                   "alone, leaving the cores to the encoder")
      ->check(CLI::Range(0, 64));
  render
      ->add_option("--png-workers", render_options.png_workers,
                   "PNG sequence: threads compressing frames")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  render->add_option("--png-level", render_options.png_level, "PNG: zlib level 0..9")
      ->capture_default_str();
  render
      ->add_option("--png-filter", render_options.png_filter,
                   "PNG: row filter none, sub, up, average, paeth or all (adaptive)")
      ->capture_default_str();
  render->footer(
      "Examples:\n"
      "  rugosim render scenes/figure12a.json -o out/figure12a.mp4\n"
      "  rugosim render scenes/figure12a.json -o out/frames/f_%04d.png --frames 0:59 --size "
      "1920x1080\n"
      "  rugosim render scenes/figure12b.json -o out/strip.png --strip 6 --size 480x360\n"
      "An existing OUT is kept unless -y is given. On Ctrl-C the frame in hand is finished, the "
      "output is closed (a playable MP4) and the exit code is 130.");

  SnapshotOptions snap;
  CLI::App* snapshot = app.add_subcommand(
      "snapshot", "visual regression: render frames and compare them with golden PNGs");
  snapshot->add_option("SCENE", snap.scene_path, "scene file (JSON)")->required();
  snapshot
      ->add_option("--golden", snap.golden_dir,
                   "folder of the goldens: SCENE-STEM_FRAME.png and SCENE-STEM.json")
      ->required()
      ->type_name("DIR");
  snapshot
      ->add_option("--frames", snap.frames,
                   "frames to check: 0,30,60 or ranges A:B, A:B:STEP (default: the goldens' "
                   "frames, or 4 spread over the clip)")
      ->type_name("LIST");
  snapshot
      ->add_option("--output", snap.output_dir,
                   "folder for a failure's actual and diff images and summary (default: "
                   "the golden folder), e.g. to upload as CI artifacts")
      ->type_name("DIR");
  snapshot->add_flag("--update", snap.update, "write the goldens (and their .json) instead");
  snapshot->add_flag("--exact", snap.exact, "fail on any difference");
  snapshot
      ->add_option("--threshold", snap.threshold,
                   "a pixel differs when a channel differs by more than this (0..255)")
      ->capture_default_str();
  snapshot
      ->add_option("--max-share", snap.max_share,
                   "fail when more than this share of pixels differ (0..1)")
      ->capture_default_str();
  snapshot->add_flag("--json", snap.json, "print the comparison as JSON on stdout");
  snapshot->add_option("--size", snap.size, "frame size (default: the goldens', or render.size)")
      ->type_name("WxH");
  snapshot->add_option("--backend", snap.backend, "OpenGL backend: osmesa or egl")
      ->capture_default_str();
  snapshot->add_option("--aa", snap.anti_aliasing, "anti-aliasing: shader, msaa or none")
      ->capture_default_str();
  add_accuracy_options(*snapshot, snap.accuracy);
  snap.threads = cpus;
  add_threads_option(*snapshot, snap.threads);
  snapshot->footer(
      "Examples:\n"
      "  rugosim snapshot scenes/figure12a.json --golden tests/goldens --size 320x180 --update\n"
      "  rugosim snapshot scenes/figure12a.json --golden tests/goldens --json\n"
      "Exit 0 when every frame matches, 1 when one differs or is missing (NAME_FRAME.actual.png, "
      "NAME_FRAME.diff.png and NAME.summary.txt are written beside the goldens), 2 for bad "
      "usage, a bad scene or an unreadable golden.");

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
    return run_simulate(sim);
  }
  if (render->parsed()) {
    if (render->count("--fps") > 0) render_options.fps = render_fps;
    if (render->count("--duration") > 0) render_options.duration = render_duration;
    if (render->count("--gl-threads") > 0) render_options.gl_threads = gl_threads;
    if (render->count("--overlay") > 0) {
      std::erase(overlays, std::string("none"));
      render_options.overlays = overlays;
    }
    return run_render(render_options);
  }
  if (snapshot->parsed()) return run_snapshot(snap);
  if (plot->parsed()) {
    plot_options.contacts = !no_contacts;
    return run_plot(plot_options);
  }
  fmt::print("{}", app.help());
  return kExitOk;
}
