// The subcommands of the rugosim program (INTERFACE.md, "Command line"). Each returns the
// process's exit code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/app/scene_input.h"

namespace rugosim::app {

// Exit 0 and a summary, or 2 and every error found.
int run_validate(const std::string& scene_path);

// Per body: segments, area, mass, centroid, inertia, range of λ, tree depth; as a table or as
// JSON (`{"bodies": [...]}`).
int run_info(const std::string& scene_path, bool json);

struct SimulateOptions {
  std::string scene_path;
  std::optional<double> duration;  // s, overrides world.duration
  std::optional<double> fps;       // overrides render.fps: the trajectory's frame rate
  AccuracyOverride accuracy;
  int threads = 1;              // of collision detection (--threads)
  bool strict = false;          // exit 1 when a crossing state was accepted (crossing_report.h)
  std::string trajectory_path;  // empty: not written
  std::string events_path;
  std::string stats_path;
  std::string checkpoint_dir;  // --checkpoints: empty for none
  std::size_t every = 30;      // --every: frames between checkpoints
  std::string resume_path;     // --resume: a checkpoint to continue from
};

// Simulates and writes the telemetry files atomically; exit 130 on SIGINT after writing what
// was simulated so far. With checkpoint_dir, the World's exact state is written there at every
// `every`-th frame (checkpoint_file.h); with resume_path, the run continues from such a
// checkpoint, and its telemetry holds the frames after it.
int run_simulate(const SimulateOptions& options);

struct RenderOptions {
  std::string scene_path;
  std::string output;  // clip.mp4 (.gif, .webm, .mov, .webp), a PNG pattern like
                       // out/f_%04d.png, or one PNG (--frame: a still, --strip: a strip)
  std::string
      format;  // "mp4", "gif", "webm", "mov", "webp", "png", "svg" or "pdf"; empty: the name
  std::string frames;                // "A:B", inclusive; empty: the whole clip
  std::optional<std::size_t> frame;  // --frame K: one still PNG of frame K
  std::string camera;  // --camera auto | CX,CY,HEIGHT | follow:BODY[,HEIGHT]; empty: render.camera
  std::string size;    // "WxH"; empty: render.size
  std::optional<double> roughness_scale;  // replaces render.roughness_scale
  std::optional<double> fps;
  std::optional<double> duration;
  AccuracyOverride accuracy;
  int threads = 1;      // of collision detection (--threads)
  bool strict = false;  // exit 1 when a crossing state was accepted (crossing_report.h)
  int crf = 18;
  std::string preset = "medium";
  bool overwrite = false;  // -y
  std::string backend = "osmesa";
  std::string anti_aliasing = "shader";
  std::optional<std::vector<std::string>> overlays;  // replaces render.overlays
  std::size_t strip = 0;                             // > 0: one PNG of this many frames
  std::size_t columns = 0;                           // frames per row of a strip; 0: one row
  std::optional<int> gap;     // px between a strip's frames; default: frame width / 160, ≥ 2
  bool strip_labels = false;  // the time under each frame of a strip
  int png_level = 1;
  std::string png_filter = "up";
  std::optional<int> gl_threads;  // llvmpipe rasteriser threads (LP_NUM_THREADS)
  int png_workers = 2;            // threads compressing a PNG sequence
  std::string chunk;              // --chunk I/N or auto/N (render_chunk.h); empty: the whole clip
  std::string checkpoint_dir;     // --checkpoints: where a chunk finds its checkpoints
};

// Renders a scene to a clip (MP4, GIF, WebM, MOV, WebP), a PNG sequence, a still or a strip. Exit 2
// for bad options or a bad scene (nothing written), 1 for a GL, encoder or I/O failure, 130 on
// SIGINT after closing the output so that it holds every frame rendered.
int run_render(const RenderOptions& options);

struct SnapshotOptions {
  std::string scene_path;
  std::string golden_dir;  // DIR: <stem>_<frame>.png goldens and <stem>.json beside them
  std::string frames;      // "0,30,60" or ranges "0:90:30"; empty: the goldens' frames, or 4
                           // spread over the clip
  std::string output_dir;  // where a failure's actual, diff and summary go; empty: golden_dir
  bool update = false;     // write the goldens instead of comparing
  bool exact = false;
  int threshold = 16;        // per-channel difference a pixel may have (0..255)
  double max_share = 0.001;  // share of pixels allowed past the threshold
  bool json = false;         // the comparison as JSON on stdout
  std::string size;          // "WxH"; empty: the goldens' size, or render.size
  std::string backend = "osmesa";
  std::string anti_aliasing = "shader";
  AccuracyOverride accuracy;
  int threads = 1;      // of collision detection (--threads)
  bool strict = false;  // exit 1 when the run had to accept a crossing state
};

// Renders frames of a scene and compares them with golden PNGs (INTERFACE.md, `snapshot`), or
// writes the goldens with --update. Exit 0 when every frame passes (or was written), 1 when one
// fails or is missing (an `actual` and a `diff` image and a summary are written next to the
// goldens), or with --strict when the simulation accepted a crossing state (crossing_report.h),
// 2 for bad usage, a bad scene or an unreadable golden.
int run_snapshot(const SnapshotOptions& options);

struct PlotOptions {
  std::string events_path;      // empty: no friction plot
  std::string trajectory_path;  // empty: no velocity plot
  std::string output_dir;       // created when missing
  // --bodies values, each a comma-separated list of names (quoted as in CSV when a name holds a
  // comma); empty: every body of the trajectory.
  std::vector<std::string> bodies;
  bool contacts = true;        // draw the micro-collisions (kind "contact") under the collisions
  std::string format = "png";  // png, svg or pdf: DIR/friction.<format>, DIR/velocity.<format>
  std::string size;            // "WxH" px (a PDF: hundredths of an inch); empty: 1000x600
};

// Draws DIR/friction.png (μ of each collision event over time, paper fig. 8) and
// DIR/velocity.png (speed and vx of the bodies over time, figs. 10, 11) with gnuplot, from
// whichever of the two CSVs is given. Exit 2 for a bad or missing CSV or an unknown body (no
// PNG is written), 1 when gnuplot is missing or fails.
int run_plot(const PlotOptions& options);

struct PlanOptions {
  std::string scene_path;
  std::string output;          // OUT.mp4 of the render
  std::size_t chunks = 0;      // N
  std::size_t every = 30;      // frames between checkpoints
  std::string checkpoint_dir;  // empty: OUT.mp4.checkpoints
  AccuracyOverride accuracy;   // passed to the pass and the chunks alike
  std::optional<double> fps;
  std::string size;  // --size WxH of the chunks; empty: render.size
  std::optional<int> crf;
  std::string program = "rugosim";  // how the tasks call the program
  int jobs = 2;                     // GNU parallel's -j
};

// Prints the commands and recipes of a chunked render (plan_command.cpp); runs nothing.
int run_plan_render(const PlanOptions& options);

struct JoinOptions {
  std::string output;      // OUT.mp4: the chunks are OUT.chunkI.mp4 (render_chunk.h)
  std::size_t chunks = 0;  // N
  bool overwrite = false;  // -y
};

// Concatenates the N chunks of `render --chunk I/N` into OUT without re-encoding (mp4_join.h),
// atomically. Exit 2 for a missing chunk or chunks encoded with other settings (nothing
// written), 1 for an I/O failure.
int run_join(const JoinOptions& options);

struct SweepOptions {
  std::string spec_path;
  std::string output_dir;  // -o: the sweep's folder; empty: SPEC's path without .json + ".sweep"
  bool list = false;       // --list: print the tasks (and which are done)
  std::string task;        // --task I or auto; empty: none
  bool gather = false;     // --gather: sweep.csv and the plots
  bool overwrite = false;  // -y: redo a task whose folder holds another sweep's result
  int threads = 1;         // of collision detection in each task (--threads)
  std::string plot_format = "png";  // --plot-format png, svg or pdf
};

// A parameter sweep (sweep_spec.h; docs/sweeps.md): --list prints the tasks, --task runs one
// into DIR/task_NNNNNN (atomically; a task already done is skipped), --gather writes DIR/sweep.csv
// and DIR/plots. Exit 2 for a bad spec or option (every error: file, JSON path, expectation), 1
// when --gather finds tasks not done or a task fails; a task's own exit code otherwise.
int run_sweep(const SweepOptions& options);

}  // namespace rugosim::app
