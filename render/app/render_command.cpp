#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <vector>

#include <fmt/core.h>

#include "engine/core/hash.h"
#include "engine/dynamics/state_hash.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "render/app/atomic_file.h"
#include "render/app/checkpoint_file.h"
#include "render/app/clip_render.h"
#include "render/app/commands.h"
#include "render/app/crossing_report.h"
#include "render/app/frame_memory.h"
#include "render/app/number_option.h"
#include "render/app/progress.h"
#include "render/app/render_chunk.h"
#include "render/app/render_scene.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "render/sinks/atomic_output_file.h"
#include "render/sinks/encoded_clip_sink.h"
#include "render/sinks/film_strip.h"
#include "render/sinks/mp4_join.h"
#include "render/sinks/mp4_sink.h"
#include "render/sinks/png_io.h"
#include "render/sinks/png_sequence_sink.h"
#include "render/sinks/vector_still.h"
#include "render/text/frame_text.h"

namespace rugosim::app {
namespace {

// What -o (and --format) ask for: a clip (MP4, or GIF, WebM, MOV, WebP: encoded_clip_sink.h),
// every frame as PNG files, or one PNG of one frame (a still) or of several (a strip).
enum class OutputKind { kMp4, kClip, kPngSequence, kPngStill, kStrip, kVectorStill };

struct Output {
  OutputKind kind = OutputKind::kMp4;
  ClipFormat clip = ClipFormat::kGif;        // of kClip
  VectorFormat vector = VectorFormat::kSvg;  // of kVectorStill
};

bool writes_one_png(OutputKind kind) {
  return kind == OutputKind::kPngStill || kind == OutputKind::kStrip ||
         kind == OutputKind::kVectorStill;
}

// A usage error: printed as "error: ..." with exit code 2, before anything is written.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::size_t parse_count(std::string_view text, std::string_view what) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    throw UsageError(fmt::format("{}: expected a whole number, got \"{}\"", what, text));
  }
  return value;
}

// A file name's extension, lower case, with its dot ("" when it has none).
std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

Output output_kind(const RenderOptions& o) {
  const std::string ext = extension_of(o.output);
  const std::string named = ext.empty() ? ext : ext.substr(1);
  const bool known = named == "mp4" || named == "png" || named == "svg" || named == "pdf" ||
                     parse_clip_format(named).has_value();
  // A file named for one format holding another is a mistake (a name without one of these
  // extensions, such as /dev/null, takes any --format).
  if (!o.format.empty() && known && named != o.format) {
    throw UsageError(fmt::format("-o {} with --format {}: the name says {}; make them agree",
                                 o.output, o.format, named));
  }
  if (o.strip > 0) {
    if (o.frame) {
      throw UsageError("--frame K writes one frame, --strip N several side by side: give one");
    }
    if (!o.format.empty() && o.format != "png") {
      throw UsageError("--strip writes one PNG: --format must be png");
    }
    if (named != "png" && o.format.empty()) {
      throw UsageError(fmt::format(
          "-o {}: --strip writes one PNG, so OUT must end in .png (or give --format png)",
          o.output));
    }
    return {OutputKind::kStrip};
  }
  const std::string format = o.format.empty() ? named : o.format;
  if (format == "svg" || format == "pdf") {
    if (!o.frame) {
      throw UsageError(fmt::format(
          "-o {}: {} holds one still: add --frame K (for a clip write .mp4, .gif, .webm, .mov "
          "or .webp)",
          o.output, format == "svg" ? "an SVG" : "a PDF"));
    }
    Output out{OutputKind::kVectorStill};
    out.vector = format == "svg" ? VectorFormat::kSvg : VectorFormat::kPdf;
    return out;
  }
  const std::optional<ClipFormat> clip = parse_clip_format(format);
  if (format == "mp4" || clip) {
    if (o.frame) {
      throw UsageError(fmt::format(
          "--frame K writes one still PNG, not a clip; for part of a clip use --frames A:B"));
    }
    return clip ? Output{OutputKind::kClip, *clip} : Output{OutputKind::kMp4};
  }
  if (format == "png") {
    if (is_png_pattern(o.output)) {
      if (o.frame) {
        throw UsageError(
            fmt::format("-o {}: --frame K writes one still, so OUT is a file name without %d (e.g. "
                        "still.png); for several frames use --frames A:B",
                        o.output));
      }
      return {OutputKind::kPngSequence};
    }
    if (o.frame) return {OutputKind::kPngStill};
    throw UsageError(fmt::format(
        "-o {}: one PNG file holds one frame: add --frame K for a still or --strip N for a "
        "strip, or give a pattern with one %d, %Nd or %0Nd (e.g. out/f_%04d.png) for every frame",
        o.output));
  }
  throw UsageError(fmt::format(
      "-o {}: cannot tell the output format; expected a name ending in .mp4, .gif, .webm, .mov "
      "or .webp, a PNG pattern like out/f_%04d.png, a .png with --frame K or --strip N, an .svg "
      "or .pdf with --frame K, or --format mp4|gif|webm|mov|webp|png|svg|pdf",
      o.output));
}

// --camera: "auto", "CX,CY,HEIGHT" in metres, or "follow:BODY[,HEIGHT]" (the scene's
// render.camera keys). A followed body must be one of `scene`'s.
CameraSpec camera_option(const std::string& text, const Scene& scene) {
  CameraSpec camera;
  if (text == "auto") return camera;
  constexpr std::string_view kFollow = "follow:";
  if (text.starts_with(kFollow)) {
    const std::string rest = text.substr(kFollow.size());
    const std::size_t comma = rest.rfind(',');
    camera.automatic = false;
    camera.follow = rest.substr(0, comma);
    if (comma != std::string::npos) {
      const std::optional<double> height = parse_number(rest.substr(comma + 1), false);
      if (!height || !(*height > 0.0)) {
        throw UsageError(fmt::format(
            "--camera: expected follow:BODY or follow:BODY,HEIGHT (HEIGHT > 0 m), got \"{}\"",
            text));
      }
      camera.height = *height;
    }
    if (!find_body(scene, camera.follow)) {
      throw UsageError("--camera: " + unknown_body_message(scene, camera.follow));
    }
    return camera;
  }
  std::vector<double> numbers;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::optional<double> x = parse_number(text.substr(start, comma - start), false);
    if (!x) break;
    numbers.push_back(*x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (numbers.size() != 3 || !(numbers[2] > 0.0)) {
    throw UsageError(
        fmt::format("--camera: expected auto, CX,CY,HEIGHT in metres (HEIGHT > 0, e.g. "
                    "0,1.1,2.6) or follow:BODY[,HEIGHT], got \"{}\"",
                    text));
  }
  camera.automatic = false;
  camera.center = Vec2(numbers[0], numbers[1]);
  camera.height = numbers[2];
  return camera;
}

// Regular files are not overwritten without -y (for a sequence: none of its frames' files);
// devices and pipes (/dev/null, /dev/full, a FIFO) are written to as they are.
void refuse_to_overwrite(const std::string& path, bool overwrite) {
  struct stat info {};
  if (!overwrite && ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    throw UsageError(fmt::format("{} exists; add -y to overwrite it", path));
  }
}

struct FrameRange {
  std::size_t first = 0;
  std::size_t last = 0;
};

FrameRange frame_range(const std::string& text, std::size_t last_frame) {
  if (text.empty()) return {0, last_frame};
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    throw UsageError(
        fmt::format("--frames: expected A:B (inclusive, e.g. 0:59), got \"{}\"", text));
  }
  const FrameRange range{parse_count(text.substr(0, colon), "--frames A"),
                         parse_count(text.substr(colon + 1), "--frames B")};
  if (range.first > range.last) {
    throw UsageError(fmt::format("--frames {}: A must not be after B", text));
  }
  if (range.last > last_frame) {
    throw UsageError(
        fmt::format("--frames {}: the clip's last frame is {} (duration × fps)", text, last_frame));
  }
  return range;
}

std::pair<int, int> frame_size(const std::string& text, const Scene& scene, OutputKind kind) {
  int width = scene.render.width;
  int height = scene.render.height;
  if (!text.empty()) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) {
      throw UsageError(fmt::format("--size: expected WxH (e.g. 1280x720), got \"{}\"", text));
    }
    width = static_cast<int>(parse_count(text.substr(0, x), "--size W"));
    height = static_cast<int>(parse_count(text.substr(x + 1), "--size H"));
  }
  if (width < 2 || height < 2 || width > 16384 || height > 16384) {
    throw UsageError(
        fmt::format("frame size {}x{}: expected 2..16384 pixels a side", width, height));
  }
  if (kind == OutputKind::kMp4 && (width % 2 != 0 || height % 2 != 0)) {
    throw UsageError(fmt::format(
        "frame size {}x{}: an MP4 (H.264, yuv420p) needs an even width and height", width, height));
  }
  return {width, height};
}

struct Plan {
  OutputKind kind = OutputKind::kMp4;
  StripGrid strip;                  // of OutputKind::kStrip
  std::vector<std::string> labels;  // a strip's time labels, one per frame (--strip-labels)
  ClipFormat clip_format = ClipFormat::kGif;        // of OutputKind::kClip
  VectorFormat vector_format = VectorFormat::kSvg;  // of OutputKind::kVectorStill
  bool transparent = false;                         // render.background "transparent": keep alpha
  FrameRange range;
  ClipPlan clip;  // frames to draw, fps, size, backend, anti-aliasing, overlays
  PngSettings png;
  Mp4Options mp4;
};

// A strip's grid, its labels and, without --size, a frame size that keeps it at most 4,000 px
// wide (a slide's or a page's width at print resolution).
void plan_strip(const RenderOptions& o, const Scene& scene, Plan& plan) {
  constexpr int kWidest = 4000;
  const auto count = static_cast<int>(plan.clip.frames.size());
  const int columns = o.columns > 0 ? std::min(static_cast<int>(o.columns), count) : count;
  const auto gap_for = [&](int width) { return o.gap.value_or(std::max(2, width / 160)); };
  if (o.size.empty() &&
      columns * plan.clip.width + (columns - 1) * gap_for(plan.clip.width) > kWidest) {
    const int width = std::max(2, (kWidest - (columns - 1) * gap_for(plan.clip.width)) / columns);
    plan.clip.height =
        std::max(2, static_cast<int>(std::lround(static_cast<double>(width) * plan.clip.height /
                                                 static_cast<double>(plan.clip.width))));
    plan.clip.width = width;
  }
  plan.strip = StripGrid{columns, gap_for(plan.clip.width),
                         o.strip_labels ? strip_label_band(plan.clip.height) : 0};
  if (o.strip_labels) {
    const std::string format = scene.render.clock ? scene.render.clock->format : "t = %.2f s";
    for (const std::size_t k : plan.clip.frames)
      plan.labels.push_back(clock_text(format, static_cast<double>(k) / plan.clip.fps));
  }
}

Plan make_plan(const RenderOptions& o, const LoadedScene& loaded) {
  Plan plan;
  const Output output = output_kind(o);
  plan.kind = output.kind;
  plan.clip_format = output.clip;
  plan.vector_format = output.vector;
  const Scene& scene = loaded.scene;
  plan.clip.fps = o.fps.value_or(scene.render.fps);
  const double duration = o.duration.value_or(scene.duration);
  const RunFrames run =
      run_frames(duration, o.duration ? "--duration" : "world.duration", plan.clip.fps,
                 o.fps ? "--fps" : "render.fps", loaded.world->settings().min_step);
  if (!run.error.empty()) throw UsageError(run.error);
  const std::size_t last = run.last;
  if (o.frame && !o.frames.empty()) {
    throw UsageError("--frame K (one still) and --frames A:B (a range): give one");
  }
  if (o.frame && *o.frame > last) {
    throw UsageError(
        fmt::format("--frame {}: the clip's last frame is {} (duration × fps)", *o.frame, last));
  }
  plan.range = o.frame ? FrameRange{*o.frame, *o.frame} : frame_range(o.frames, last);
  if (plan.kind == OutputKind::kClip && plan.clip_format == ClipFormat::kGif &&
      !clip_fps_is_valid(ClipFormat::kGif, plan.clip.fps)) {
    throw UsageError(fmt::format(
        "{} {:g}: a GIF plays at most 50 frames per second (its delays are whole centiseconds "
        "and browsers slow delays under 2 cs); use --fps 50 or less",
        o.fps ? "--fps" : "render.fps", plan.clip.fps));
  }
  if (plan.kind == OutputKind::kStrip) {
    plan.clip.frames = strip_frame_indices(plan.range.first, plan.range.last, o.strip);
  } else {
    for (std::size_t k = plan.range.first; k <= plan.range.last; ++k)
      plan.clip.frames.push_back(k);
  }
  std::tie(plan.clip.width, plan.clip.height) = frame_size(o.size, scene, plan.kind);
  if (plan.kind != OutputKind::kStrip && (o.columns > 0 || o.gap || o.strip_labels)) {
    throw UsageError(
        "--columns, --gap and --strip-labels lay out a strip: expected --strip N with them");
  }
  if (plan.kind == OutputKind::kStrip) plan_strip(o, scene, plan);
  const std::optional<GlBackend> backend = parse_gl_backend(o.backend);
  if (!backend) throw UsageError("--backend: expected osmesa or egl, got \"" + o.backend + "\"");
  plan.clip.backend = *backend;
  const std::optional<AntiAliasing> aa = parse_anti_aliasing(o.anti_aliasing);
  if (!aa) {
    throw UsageError("--aa: expected shader, msaa or none, got \"" + o.anti_aliasing + "\"");
  }
  plan.clip.anti_aliasing = *aa;
  std::string unknown;
  const std::optional<Overlays> overlays =
      parse_overlays(o.overlays.value_or(scene.render.overlays), &unknown);
  if (!overlays) {
    throw UsageError("--overlay: unknown overlay \"" + unknown +
                     "\"; expected rugosity, contacts or velocity");
  }
  plan.clip.overlays = *overlays;
  if (o.png_level < 0 || o.png_level > 9) {
    throw UsageError(fmt::format("--png-level: expected 0..9, got {}", o.png_level));
  }
  plan.png.level = o.png_level;
  const std::optional<PngFilter> filter = parse_png_filter(o.png_filter);
  if (!filter) {
    throw UsageError("--png-filter: expected none, sub, up, average, paeth or all, got \"" +
                     o.png_filter + "\"");
  }
  plan.png.filter = *filter;
  plan.transparent = has_transparent_background(scene);
  plan.png.keep_alpha = plan.transparent;
  if (plan.transparent && plan.kind == OutputKind::kMp4) {
    throw UsageError(
        "render.background is \"transparent\" but an MP4 (H.264) has no alpha: write .webm, "
        ".mov, .webp, .gif or PNG, or give the scene a background colour");
  }
  if (!mp4_crf_is_valid(o.crf))
    throw UsageError(fmt::format("--crf: expected 0..51, got {}", o.crf));
  if (!mp4_preset_is_valid(o.preset)) {
    throw UsageError(
        "--preset: expected an x264 preset (ultrafast, superfast, veryfast, faster, "
        "fast, medium, slow, slower, veryslow, placebo), got \"" +
        o.preset + "\"");
  }
  plan.mp4.fps = plan.clip.fps;
  plan.mp4.crf = o.crf;
  plan.mp4.preset = o.preset;
  if (!o.chunk.empty()) {
    // A chunk writes OUT.chunkI.mp4 (render_chunk.h), never OUT; a complete one is skipped.
    if (plan.kind != OutputKind::kMp4)
      throw UsageError("--chunk: expected an MP4 output (-o OUT.mp4)");
    if (o.frame || !o.frames.empty() || o.strip > 0)
      throw UsageError("--chunk splits the whole clip: not with --frame, --frames or --strip");
  } else if (plan.kind == OutputKind::kPngSequence) {
    for (const std::size_t frame : plan.clip.frames) {
      refuse_to_overwrite(format_frame_path(o.output, frame), o.overwrite);
    }
  } else {
    refuse_to_overwrite(o.output, o.overwrite);
  }
  return plan;
}

}  // namespace

// A chunk of the clip (render_chunk.h): narrows the plan to the chunk's frames, restores the World
// from the latest checkpoint before them and frames the automatic camera from the clip's last
// checkpoint. Sets `output` to the chunk's file. Returns an exit code when there is nothing to
// render: 0 when the chunk is already complete, 2 after printing why it cannot be rendered.
std::optional<int> prepare_chunk(const RenderOptions& o, LoadedScene& loaded, Plan& plan,
                                 std::string& output) {
  ChunkIndex chunk;
  try {
    chunk = parse_chunk(o.chunk);
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }
  const std::size_t last = plan.clip.frames.back();
  const auto [first, end] = chunk_frames(chunk, plan.clip.frames.size());
  if (first == end) {
    fmt::print(stderr, "error: --chunk {}: the clip has {} frames, fewer than {} chunks\n", o.chunk,
               plan.clip.frames.size(), chunk.count);
    return kExitUsage;
  }
  output = chunk_path(o.output, chunk.index);
  try {
    const Checkpoint run = run_identity(o.scene_path, scene_accuracy(loaded.scene), plan.clip.fps);
    // Which render this is: a complete chunk of the same one is skipped, another is not reused.
    Fnv1a render;
    for (const std::string& part :
         {run.program_version, run.build, run.settings,
          fmt::format("scene={:016x} frames={} size={}x{} crf={} preset={} backend={} aa={} "
                      "camera={} roughness={} overlays={}{}{}",
                      run.scene_hash, plan.clip.frames.size(), plan.clip.width, plan.clip.height,
                      o.crf, o.preset, o.backend, o.anti_aliasing, o.camera,
                      o.roughness_scale.value_or(-1.0), plan.clip.overlays.rugosity,
                      plan.clip.overlays.contacts, plan.clip.overlays.velocity)})
      render.add(std::string_view(part));
    plan.mp4.comment = chunk_tag(chunk, render.value());
    std::error_code missing;
    if (std::filesystem::exists(output, missing) && !o.overwrite) {
      std::string found;
      try {
        found = mp4_comment(output);
      } catch (const SinkError&) {
      }
      if (found == plan.mp4.comment) {
        fmt::print(stderr, "done: chunk {} of {} ({}) is already complete\n", chunk.index,
                   chunk.count, output);
        return kExitOk;
      }
      fmt::print(stderr,
                 "error: {} exists but is not chunk {} of {} of this render (another scene, "
                 "settings, options or build made it); add -y to render it again\n",
                 output, chunk.index, chunk.count);
      return kExitUsage;
    }
    const ChunkStart start = find_chunk_start(o.checkpoint_dir, run, first, last);
    if (start.state) {
      loaded.world->restore_state(start.state->world_state);
      if (full_state_hash(*loaded.world) != start.state->state_hash) {
        throw CheckpointError(fmt::format("{}: corrupt (the restored state's hash differs)",
                                          checkpoint_path(o.checkpoint_dir, start.state->frame)));
      }
      plan.clip.start_reached = start.state->frame;
    }
    plan.clip.clip_bounds = start.clip_bounds;
  } catch (const std::runtime_error& e) {  // CheckpointError, ByteStreamError
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }
  plan.clip.frames.assign(plan.clip.frames.begin() + static_cast<std::ptrdiff_t>(first),
                          plan.clip.frames.begin() + static_cast<std::ptrdiff_t>(end));
  // Every chunk starts on an IDR frame (a new encoder) with the same headers: stitchable.
  plan.mp4.stitchable = true;
  return std::nullopt;
}

// Simulates to the still's frame and writes it as SVG or PDF (whole, or not at all).
int write_vector(const RenderOptions& o, const Plan& plan, LoadedScene& loaded) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<StillFrame> still =
      simulate_still(loaded, plan.clip, &SigintGuard::interrupted());
  CrossingWatch().check(*loaded.world, stderr);
  if (!still) {
    fmt::print(stderr, "interrupted: nothing written to {}\n", o.output);
    return kExitInterrupted;
  }
  std::vector<std::uint8_t> bytes;
  try {
    bytes = make_vector_still(plan.vector_format, still->looks, still->settings, still->frame,
                              still->text);
  } catch (const std::runtime_error& e) {
    throw SinkError(fmt::format("{}: {}", o.output, e.what()));
  }
  write_file_atomically(o.output, bytes, AtomicOutputFile::Flush::kRenameOnly);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print(stderr, "done: 1 frame written to {} in {:.3g} s ({} KB, vector)\n", o.output, seconds,
             (bytes.size() + 1023) / 1024);
  return strict_exit_code(*loaded.world, o.strict, kExitOk, stderr);
}

int run_render(const RenderOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy, o.threads);
  if (!loaded) return kExitUsage;
  Plan plan;
  std::string output = o.output;  // a chunk's own file (render --chunk)
  try {
    if (!o.camera.empty()) {
      loaded->scene.render.camera = camera_option(o.camera, loaded->scene);
    }
    if (o.roughness_scale) loaded->scene.render.roughness_scale = *o.roughness_scale;
    plan = make_plan(o, *loaded);
    if (!o.chunk.empty()) {
      if (const std::optional<int> code = prepare_chunk(o, *loaded, plan, output)) return *code;
    }
  } catch (const UsageError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }
  choose_rasteriser_threads(o.gl_threads);
  keep_frame_memory();
  const SigintGuard sigint;
  try {
    std::optional<RenamedFile> chunk_file;  // declared before the sink: removed after it closes
    std::unique_ptr<FrameSink> sink;
    std::vector<Image> kept;  // the frames of a still or a strip
    if (plan.kind == OutputKind::kMp4) {
      quiet_ffmpeg_logs();
      // A chunk is written under a temporary name and renamed when whole: a chunk file that
      // exists is complete (a preempted task leaves none, and a rerun redoes it).
      if (output != o.output) chunk_file.emplace(output);
      sink = std::make_unique<Mp4Sink>(chunk_file ? chunk_file->temporary() : output,
                                       plan.clip.width, plan.clip.height, plan.mp4);
    } else if (plan.kind == OutputKind::kClip) {
      quiet_ffmpeg_logs();
      sink = std::make_unique<EncodedClipSink>(o.output, plan.clip_format, plan.clip.width,
                                               plan.clip.height,
                                               ClipOptions{plan.clip.fps, plan.transparent});
    } else if (plan.kind == OutputKind::kPngSequence) {
      sink = std::make_unique<PngSequenceSink>(o.output, plan.png, o.png_workers);
    } else {
      // A still or a strip is written at the end: a folder that is not there fails now, not
      // after rendering.
      const std::filesystem::path folder = std::filesystem::path(o.output).parent_path();
      if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw SinkError(fmt::format("{}: No such file or directory (the folder of the {})",
                                    folder.string(),
                                    plan.kind == OutputKind::kStrip ? "strip" : "still"));
      }
    }
    if (plan.kind == OutputKind::kVectorStill) return write_vector(o, plan, *loaded);
    Progress progress(static_cast<double>(plan.clip.frames.size()), stderr,
                      Progress::Unit::kFrames);
    std::size_t done = 0;
    const PipelineResult result = render_clip(
        *loaded, plan.clip,
        [&](const Image& image, std::size_t frame) {
          if (sink) {
            sink->write(image, frame);
          } else {
            kept.push_back(image);
          }
          progress.update(static_cast<double>(++done));
        },
        &SigintGuard::interrupted());
    progress.finish();
    if (sink) sink->close();
    if (chunk_file && !result.interrupted) chunk_file->commit();
    if (plan.kind == OutputKind::kStrip && !result.interrupted) {
      Image strip =
          compose_film_grid(kept, plan.strip,
                            plan.transparent ? std::array<std::uint8_t, 4>{0, 0, 0, 0}
                                             : std::array<std::uint8_t, 4>{255, 255, 255, 255});
      label_strip(strip, plan.strip, plan.clip.width, plan.clip.height, plan.labels,
                  frame_text(loaded->scene).colour);
      write_png_file(o.output, strip, plan.png);
    } else if (plan.kind == OutputKind::kPngStill && kept.size() == 1) {
      write_png_file(o.output, kept.front(), plan.png);
    }
    // The simulation runs on the pipeline's thread: its first crossing is told here, after it.
    CrossingWatch().check(*loaded->world, stderr);
    // A still or a strip is written whole or not at all: interrupted, it is not written.
    const char* where = plan.kind == OutputKind::kStrip ? "in the strip" : "written to";
    if (result.interrupted && writes_one_png(plan.kind)) where = "rendered, nothing written to";
    fmt::print(stderr, "{}: {} frame{} {} {} in {:.3g} s ({:.3g} frames/s)\n",
               result.interrupted ? "interrupted" : "done", result.frames,
               result.frames == 1 ? "" : "s", where, output, progress.wall_seconds(),
               static_cast<double>(result.frames) / std::max(progress.wall_seconds(), 1e-9));
    return strict_exit_code(*loaded->world, o.strict,
                            result.interrupted ? kExitInterrupted : kExitOk, stderr);
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
