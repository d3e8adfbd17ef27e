#include "render/app/command_line.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/core/version.h"
#include "engine/scene/scene_loader.h"
#include "render/app/accuracy_options.h"
#include "render/app/number_option.h"

namespace rugosim::app {
namespace {

// Durations are bounded by the run-length checks, which know the accuracy (run_length.h).
const NumberRange kDuration{0.0, true, std::numeric_limits<double>::infinity(), true, false, "s"};
// The bound of the scene key render.fps (INTERFACE.md).
const NumberRange kRoughnessScale{0.0, false, 100.0, false, false, "display scale"};
const NumberRange kFps{0.0, true, 1000.0, false, false, "frames per second"};
const NumberRange kEvery{1.0, false, 1e9, false, true, "frames"};

}  // namespace

std::unique_ptr<CommandLine> make_command_line(int cpus) {
  auto made = std::make_unique<CommandLine>();
  CommandLine& c = *made;
  // Usage errors read like the program's own ("error: ..."); set before the subcommands, which
  // copy it.
  c.app.failure_message([](const CLI::App* app, const CLI::Error& e) {
    return "error: " + CLI::FailureMessage::simple(app, e);
  });
  c.app.set_version_flag("--version", std::string("rugosim ") + kVersion);
  c.app.footer(
      "Exit codes: 0 success, 1 runtime failure, 2 bad usage or invalid scene, 130 interrupted.\n"
      "Run 'rugosim COMMAND --help' for a command's options and examples.");
  c.app.require_subcommand(0, 1);

  c.validate = c.app.add_subcommand("validate", "check a scene file, reporting every error");
  c.validate->add_option("SCENE", c.scene, "scene file (JSON)")->required();
  c.validate->footer("Example: rugosim validate scenes/figure12a.json");

  c.info = c.app.add_subcommand(
      "info", "per body: segments, area, mass, centroid, inertia, range of lambda, tree depth");
  c.info->add_option("SCENE", c.scene, "scene file (JSON)")->required();
  c.info->add_flag("--json", c.json, "print JSON: {\"bodies\": [{\"name\", \"segments\", ...}]}");
  c.info->footer("Example: rugosim info scenes/figure09_constant.json --json");

  c.simulate = c.app.add_subcommand("simulate", "simulate a scene and write telemetry");
  c.simulate->add_option("SCENE", c.sim.scene_path, "scene file (JSON)")->required();
  c.simulate->add_option("--duration", c.duration, "simulated time, s (default: world.duration)")
      ->check(number_in(kDuration))
      ->type_name("SECONDS");
  c.simulate->add_option("--fps", c.fps, "trajectory frames per second (default: render.fps)")
      ->check(number_in(kFps))
      ->type_name("FPS");
  add_accuracy_options(*c.simulate, c.sim.accuracy);
  c.sim.threads = cpus;
  add_threads_option(*c.simulate, c.sim.threads);
  c.simulate->add_flag("--strict", c.sim.strict,
                       "exit 1 when the run had to accept a crossing state (for CI)");
  c.simulate->add_option("--trajectory", c.sim.trajectory_path, "write trajectory.csv here");
  c.simulate->add_option("--events", c.sim.events_path, "write events.csv (one row per impulse)");
  c.simulate->add_option("--stats", c.sim.stats_path, "write stats.json (step statistics)");
  CLI::Option* checkpoints = c.simulate->add_option(
      "--checkpoints", c.sim.checkpoint_dir,
      "write the exact state every --every frames into this folder (frame_NNNNNN.ckpt)");
  c.simulate->add_option("--every", c.sim.every, "frames between checkpoints (default: 30)")
      ->check(number_in(kEvery))
      ->type_name("N")
      ->needs(checkpoints);
  c.simulate->add_option("--resume", c.sim.resume_path,
                         "continue from this checkpoint (same scene file, settings and build); "
                         "the telemetry holds the frames after it");
  c.simulate->footer(
      "Example: rugosim simulate scenes/figure12a.json --trajectory out/traj.csv "
      "--events out/events.csv --stats out/stats.json\n"
      "         rugosim simulate scenes/pile_200.json --checkpoints out/ckpt --every 15\n"
      "         rugosim simulate scenes/pile_200.json --resume out/ckpt/frame_000060.ckpt "
      "--trajectory out/rest.csv\n"
      "Files are written atomically: on an error none is created or truncated; on Ctrl-C the "
      "frames simulated so far are written and the exit code is 130.");

  c.render = c.app.add_subcommand(
      "render",
      "render a scene off-screen to a clip (MP4, GIF, WebM, MOV, WebP), a PNG sequence, a still "
      "or a film strip");
  c.render->add_option("SCENE", c.render_options.scene_path, "scene file (JSON)")->required();
  c.render
      ->add_option("-o,--output", c.render_options.output,
                   "clip.mp4, .gif, .webm, .mov or .webp, a PNG pattern like out/f_%04d.png, or "
                   "one PNG: a still (--frame K) or a strip (--strip N)")
      ->required()
      ->type_name("OUT");
  c.render
      ->add_option("--format", c.render_options.format,
                   "mp4, gif, webm, mov, webp, png, svg or pdf (default: from OUT's extension)")
      ->check(CLI::IsMember({"mp4", "gif", "webm", "mov", "webp", "png", "svg", "pdf"}));
  c.render
      ->add_option("--frames", c.render_options.frames,
                   "frames A:B, inclusive (default: 0 to duration × fps)")
      ->type_name("A:B");
  c.render
      ->add_option("--frame", c.render_options.frame,
                   "one still: frame K (0 to duration × fps) as one PNG, SVG or PDF")
      ->check(number_in({0, false, 1e9, false, true, "frame"}))
      ->type_name("K");
  c.render
      ->add_option("--camera", c.render_options.camera,
                   "auto; CX,CY,HEIGHT in metres: the view's centre and height; or "
                   "follow:BODY[,HEIGHT]: centred on that body in every frame (default: "
                   "render.camera)")
      ->type_name("C");
  c.render->add_option("--size", c.render_options.size, "frame size (default: render.size)")
      ->type_name("WxH");
  c.render
      ->add_option("--roughness-scale", c.render_roughness_scale,
                   "exaggerates the drawn rugosity detail (display only; default: "
                   "render.roughness_scale, 1)")
      ->check(number_in(kRoughnessScale))
      ->type_name("X");
  c.render->add_option("--fps", c.render_fps, "frames per second (default: render.fps)")
      ->check(number_in(kFps))
      ->type_name("FPS");
  c.render
      ->add_option("--duration", c.render_duration, "simulated time, s (default: world.duration)")
      ->check(number_in(kDuration))
      ->type_name("SECONDS");
  add_accuracy_options(*c.render, c.render_options.accuracy);
  c.render_options.threads = cpus;
  add_threads_option(*c.render, c.render_options.threads);
  c.render->add_flag("--strict", c.render_options.strict,
                     "exit 1 when the run had to accept a crossing state (for CI)");
  CLI::Option* render_checkpoints = c.render->add_option(
      "--checkpoints", c.render_options.checkpoint_dir,
      "with --chunk: the folder of `simulate --checkpoints` for this scene and settings");
  c.render
      ->add_option("--chunk", c.render_options.chunk,
                   "MP4: render chunk I of N (0-based; auto: from SLURM_ARRAY_TASK_ID, "
                   "JOB_COMPLETION_INDEX or PARALLEL_SEQ) into OUT.chunkI.mp4, for `rugosim join`")
      ->type_name("I/N")
      ->needs(render_checkpoints);
  c.render->add_option("--crf", c.render_options.crf, "MP4: x264 constant rate factor 0..51")
      ->check(number_in({0, false, 51, false, true, ""}))
      ->type_name("N")
      ->capture_default_str();
  c.render->add_option("--preset", c.render_options.preset, "MP4: x264 preset")
      ->capture_default_str();
  c.render->add_flag("-y", c.render_options.overwrite, "overwrite OUT if it exists");
  c.render->add_option("--backend", c.render_options.backend, "OpenGL backend: osmesa or egl")
      ->capture_default_str();
  c.render
      ->add_option("--aa", c.render_options.anti_aliasing,
                   "anti-aliasing: shader (edge coverage in the shaders), msaa (4x) or none")
      ->capture_default_str();
  c.render
      ->add_option("--overlay", c.overlays,
                   "overlays, replacing render.overlays: rugosity, contacts, velocity (comma "
                   "separated; \"none\" for none)")
      ->delimiter(',')
      ->type_name("LIST");
  c.render
      ->add_option("--columns", c.render_options.columns,
                   "a strip's frames per row (default: all in one row)")
      ->check(number_in({1, false, 1000, false, true, "frames"}))
      ->type_name("C");
  c.render
      ->add_option(
          "--gap", c.render_options.gap,
          "pixels between a strip's frames (default: a 160th of the frame width, at least 2)")
      ->check(number_in({0, false, 1000, false, true, "px"}))
      ->type_name("PX");
  c.render->add_flag("--strip-labels", c.render_options.strip_labels,
                     "write each strip frame's time under it (render.clock's format)");
  c.render
      ->add_option("--strip", c.render_options.strip,
                   "write one PNG of N frames spread over the clip, side by side")
      ->check(number_in({1, false, 1000, false, true, "frames"}))
      ->type_name("N");
  c.render
      ->add_option("--gl-threads", c.gl_threads,
                   "llvmpipe rasteriser threads (LP_NUM_THREADS); default 0: the render thread "
                   "alone, leaving the cores to the encoder")
      ->check(number_in({0, false, 64, false, true, ""}))
      ->type_name("N");
  c.render
      ->add_option("--png-workers", c.render_options.png_workers,
                   "PNG sequence: threads compressing frames")
      ->check(number_in({1, false, 64, false, true, ""}))
      ->type_name("N")
      ->capture_default_str();
  c.render->add_option("--png-level", c.render_options.png_level, "PNG: zlib level 0..9")
      ->check(number_in({0, false, 9, false, true, ""}))
      ->type_name("N")
      ->capture_default_str();
  c.render
      ->add_option("--png-filter", c.render_options.png_filter,
                   "PNG: row filter none, sub, up, average, paeth or all (adaptive)")
      ->capture_default_str();
  c.render->footer(
      "Examples:\n"
      "  rugosim render scenes/figure12a.json -o out/figure12a.mp4\n"
      "  rugosim render scenes/figure12a.json -o out/frames/f_%04d.png --frames 0:59 --size "
      "1920x1080\n"
      "  rugosim render scenes/figure12b.json -o out/strip.png --strip 6 --size 480x360\n"
      "  rugosim render scenes/figure12a.json -o out/figure12a.gif --size 480x270 --fps 25\n"
      "  rugosim render scenes/figure12a.json -o out/still.png --frame 90 --size 1920x1080\n"
      "  rugosim render scenes/figure12a_slide.json -o out/figure.pdf --frame 90   (vector; "
      "or .svg)\n"
      "  rugosim render scenes/figure12a_slide.json -o out/slide.webm   (VP9; .mov: ProRes 4444, "
      ".webp: animated WebP)\n"
      "  rugosim render scenes/figure12a.json -o out/grid.png --strip 6 --columns 3 "
      "--strip-labels\n"
      "  rugosim render scenes/figure12a.json -o out/close.png --frame 60 --camera 0,0.5,1.2\n"
      "  rugosim render scenes/figure12a.json -o out/rock.mp4 --camera follow:rock_3,1.2\n"
      "  rugosim render scenes/figure12a.json -o out/slide.png --frame 90 --roughness-scale 3\n"
      "With render.background \"transparent\" in the scene, PNG, GIF, WebM, MOV, WebP, SVG and PDF "
      "keep "
      "alpha (an MP4 is refused). An existing OUT is kept unless -y is given. On Ctrl-C the frame "
      "in hand is finished, the output is closed (a playable MP4; a complete GIF, WebM, MOV or "
      "WebP) and the exit code is 130.");

  c.snapshot = c.app.add_subcommand(
      "snapshot", "visual regression: render frames and compare them with golden PNGs");
  c.snapshot->add_option("SCENE", c.snap.scene_path, "scene file (JSON)")->required();
  c.snapshot
      ->add_option("--golden", c.snap.golden_dir,
                   "folder of the goldens: SCENE-STEM_FRAME.png and SCENE-STEM.json")
      ->required()
      ->type_name("DIR");
  c.snapshot
      ->add_option("--frames", c.snap.frames,
                   "frames to check: 0,30,60 or ranges A:B, A:B:STEP (default: the goldens' "
                   "frames, or 4 spread over the clip)")
      ->type_name("LIST");
  c.snapshot
      ->add_option("--output", c.snap.output_dir,
                   "folder for a failure's actual and diff images and summary (default: "
                   "the golden folder), e.g. to upload as CI artifacts")
      ->type_name("DIR");
  c.snapshot->add_flag("--update", c.snap.update, "write the goldens (and their .json) instead");
  c.snapshot->add_flag("--exact", c.snap.exact, "fail on any difference");
  c.snapshot
      ->add_option("--threshold", c.snap.threshold,
                   "a pixel differs when a channel differs by more than this (0..255)")
      ->check(number_in({0, false, 255, false, true, ""}))
      ->type_name("N")
      ->capture_default_str();
  c.snapshot
      ->add_option("--max-share", c.snap.max_share,
                   "fail when more than this share of pixels differ (0..1)")
      ->check(number_in({0, false, 1, false, false, ""}))
      ->type_name("X")
      ->capture_default_str();
  c.snapshot->add_flag("--json", c.snap.json, "print the comparison as JSON on stdout");
  c.snapshot
      ->add_option("--size", c.snap.size, "frame size (default: the goldens', or render.size)")
      ->type_name("WxH");
  c.snapshot->add_option("--backend", c.snap.backend, "OpenGL backend: osmesa or egl")
      ->capture_default_str();
  c.snapshot->add_option("--aa", c.snap.anti_aliasing, "anti-aliasing: shader, msaa or none")
      ->capture_default_str();
  add_accuracy_options(*c.snapshot, c.snap.accuracy);
  c.snap.threads = cpus;
  add_threads_option(*c.snapshot, c.snap.threads);
  c.snapshot->add_flag("--strict", c.snap.strict,
                       "exit 1 when the run had to accept a crossing state (for CI)");
  c.snapshot->footer(
      "Examples:\n"
      "  rugosim snapshot scenes/figure12a.json --golden tests/goldens --size 320x180 --update\n"
      "  rugosim snapshot scenes/figure12a.json --golden tests/goldens --json\n"
      "Exit 0 when every frame matches, 1 when one differs or is missing (NAME_FRAME.actual.png, "
      "NAME_FRAME.diff.png and NAME.summary.txt are written beside the goldens), 2 for bad "
      "usage, a bad scene or an unreadable golden.");

  c.join = c.app.add_subcommand(
      "join", "concatenate the chunks of render --chunk I/N into one MP4, without re-encoding");
  c.join->add_option("OUT", c.join_options.output, "the clip: OUT.chunk0.mp4 ... are its chunks")
      ->required();
  c.join->add_option("--chunks", c.join_options.chunks, "how many chunks (N of --chunk I/N)")
      ->check(number_in({1, false, 1e6, false, true, ""}))
      ->type_name("N")
      ->required();
  c.join->add_flag("-y", c.join_options.overwrite, "overwrite OUT if it exists");
  c.join->footer(
      "Example: rugosim join out/figure12a.mp4 --chunks 4\n"
      "The chunks must come from one scene, settings and build (render --chunk I/N with the same "
      "options); OUT is a fragmented MP4 whose frames are the chunks' frames, written atomically.");

  c.plan = c.app.add_subcommand(
      "plan", "print the commands and scheduler recipes of a job that runs on many machines");
  c.plan->require_subcommand(1);
  c.plan_render = c.plan->add_subcommand(
      "render", "a chunked render: the checkpoint pass, one render per chunk, the join");
  PlanOptions& p = c.plan_options;
  c.plan_render->add_option("SCENE", p.scene_path, "scene file (JSON)")->required();
  c.plan_render->add_option("-o,--output", p.output, "the clip, OUT.mp4")->required();
  c.plan_render->add_option("--chunks", p.chunks, "how many chunks")
      ->check(number_in({1, false, 1e6, false, true, ""}))
      ->type_name("N")
      ->required();
  c.plan_render->add_option("--every", p.every, "frames between checkpoints (default: 30)")
      ->check(number_in(kEvery))
      ->type_name("N");
  c.plan_render->add_option("--checkpoints", p.checkpoint_dir,
                            "the checkpoint folder (default: OUT.mp4.checkpoints)");
  c.plan_render->add_option("--fps", c.fps, "frames per second (default: render.fps)")
      ->check(number_in(kFps))
      ->type_name("FPS");
  c.plan_render->add_option("--size", p.size, "frame size of the chunks (default: render.size)")
      ->type_name("WxH");
  c.plan_render->add_option("--crf", c.plan_crf, "x264 constant rate factor 0..51")
      ->check(number_in({0, false, 51, false, true, ""}))
      ->type_name("N");
  add_accuracy_options(*c.plan_render, p.accuracy);
  c.plan_render->add_option("--program", p.program,
                            "how the tasks call rugosim (default: rugosim, on PATH)");
  c.plan_render->add_option("--jobs", p.jobs, "GNU parallel's -j (default: 2)")
      ->check(number_in({1, false, 4096, false, true, ""}))
      ->type_name("N");
  c.plan_render->footer(
      "Example: rugosim plan render scenes/figure12a.json -o out/figure12a.mp4 --chunks 4\n"
      "Prints; runs nothing. docs/scale-out.md explains each step.");

  c.sweep = c.app.add_subcommand(
      "sweep", "run a parameter sweep: one task per point of its axes, on any task engine");
  SweepOptions& w = c.sweep_options;
  c.sweep->add_option("SPEC", w.spec_path, "the sweep spec (JSON; docs/sweeps.md)")->required();
  c.sweep->add_option("-o,--output", w.output_dir,
                      "the sweep's folder (default: SPEC without .json, plus .sweep)");
  auto* list = c.sweep->add_flag("--list", w.list, "print the tasks and which are done");
  auto* task = c.sweep
                   ->add_option("--task", w.task,
                                "run task I (0-based) into its folder, or auto: I from "
                                "SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or PARALLEL_SEQ - 1")
                   ->type_name("I|auto");
  auto* gather = c.sweep->add_flag("--gather", w.gather,
                                   "write sweep.csv (one row per task) and a plot of each measure "
                                   "against each axis");
  list->excludes(task)->excludes(gather);
  task->excludes(gather);
  c.sweep->add_flag("-y", w.overwrite,
                    "redo a task whose folder holds the result of another sweep");
  c.sweep->add_option("--plot-format", w.plot_format, "--gather's plots: png, svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->type_name("FORMAT");
  w.threads = cpus;
  add_threads_option(*c.sweep, w.threads);
  c.sweep->footer(
      "Examples:\n"
      "  rugosim sweep scenes/sweeps/incline_friction.json --list\n"
      "  seq 64 | parallel -j2 -N0 rugosim sweep scenes/sweeps/incline_friction.json --task auto\n"
      "  rugosim sweep scenes/sweeps/incline_friction.json --gather\n"
      "One of --list, --task and --gather. A task already done (its folder holds this sweep's "
      "result) is skipped, so a stopped array can be resubmitted as it is.");

  c.plot = c.app.add_subcommand(
      "plot",
      "draw friction per collision event and velocity over time as PNG, SVG or PDF (gnuplot)");
  c.plot
      ->add_option("--events", c.plot_options.events_path,
                   "events.csv: draw DIR/friction.png, mu of each collision over time")
      ->type_name("FILE.csv");
  c.plot
      ->add_option("--trajectory", c.plot_options.trajectory_path,
                   "trajectory.csv: draw DIR/velocity.png, speed |v| and vx over time")
      ->type_name("FILE.csv");
  c.plot->add_option("-o,--output", c.plot_options.output_dir, "output folder (created if missing)")
      ->required()
      ->type_name("DIR");
  c.plot
      ->add_option("--bodies", c.plot_options.bodies,
                   "bodies of the velocity plot, NAME,NAME... (default: all; quote a name that "
                   "holds a comma as in CSV)")
      ->type_name("NAME,NAME...");
  c.plot->add_flag("--no-contacts", c.no_contacts,
                   "leave out the resting-contact micro-collisions (kind \"contact\")");
  c.plot
      ->add_option("--format", c.plot_options.format,
                   "png, svg or pdf: DIR/friction.<format> and DIR/velocity.<format>")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->capture_default_str();
  c.plot
      ->add_option("--size", c.plot_options.size,
                   "figure size in pixels (a PDF: hundredths of an inch) (default: 1000x600)")
      ->type_name("WxH");
  c.plot->footer(
      "Example: rugosim plot --events out/events.csv --trajectory out/traj.csv -o out/plots "
      "--bodies 'pebble,\"disk, small\"'\n"
      "         rugosim plot --events out/events.csv -o out/paper --format pdf --size 800x500\n"
      "At least one of --events and --trajectory is needed. Requires gnuplot on PATH (Debian: "
      "gnuplot-nox). Figures are written atomically; a bad CSV leaves none (exit 2). The ten pairs "
      "with the most events get colours and legend entries; the rest are grey, counted in one "
      "entry.");

  return made;
}

void finish_parse(CommandLine& c) {
  if (c.simulate->count("--duration") > 0) c.sim.duration = c.duration;
  if (c.simulate->count("--fps") > 0) c.sim.fps = c.fps;
  if (c.plan_render->count("--fps") > 0) c.plan_options.fps = c.fps;
  if (c.plan_render->count("--crf") > 0) c.plan_options.crf = c.plan_crf;
  if (c.render->count("--fps") > 0) c.render_options.fps = c.render_fps;
  if (c.render->count("--roughness-scale") > 0) {
    c.render_options.roughness_scale = c.render_roughness_scale;
  }
  if (c.render->count("--duration") > 0) c.render_options.duration = c.render_duration;
  if (c.render->count("--gl-threads") > 0) c.render_options.gl_threads = c.gl_threads;
  if (c.render->count("--overlay") > 0) {
    std::vector<std::string> overlays = c.overlays;
    std::erase(overlays, std::string("none"));
    c.render_options.overlays = overlays;
  }
  c.plot_options.contacts = !c.no_contacts;
}

std::string unknown_command_error(const CommandLine& c, const std::string& word) {
  if (word.empty() || word.front() == '-') return {};
  std::vector<std::string> names;
  for (const CLI::App* command : c.app.get_subcommands({})) {
    if (command->get_name() == word) return {};
    names.push_back(command->get_name());
  }
  const std::string nearest = closest_match(word, names);
  if (!nearest.empty()) {
    return fmt::format("unknown command \"{}\"; did you mean \"{}\"?", word, nearest);
  }
  return fmt::format("unknown command \"{}\"; the commands are {}", word, fmt::join(names, ", "));
}

}  // namespace rugosim::app
