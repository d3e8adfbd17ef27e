#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

#include <fmt/core.h>

#include "render/app/clip_render.h"
#include "render/app/commands.h"
#include "render/app/crossing_report.h"
#include "render/app/frame_memory.h"
#include "render/app/progress.h"
#include "render/app/render_scene.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "render/sinks/film_strip.h"
#include "render/sinks/mp4_sink.h"
#include "render/sinks/png_io.h"
#include "render/sinks/png_sequence_sink.h"

namespace rugosim::app {
namespace {

enum class OutputKind { kMp4, kPngSequence, kStrip };

// A usage error: printed as "error: ..." with exit code 2, before anything is written.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

bool ends_with(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

std::size_t parse_count(std::string_view text, std::string_view what) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    throw UsageError(fmt::format("{}: expected a whole number, got \"{}\"", what, text));
  }
  return value;
}

OutputKind output_kind(const RenderOptions& o) {
  if (o.strip > 0) {
    if (!o.format.empty() && o.format != "png") {
      throw UsageError("--strip writes one PNG: --format must be png");
    }
    return OutputKind::kStrip;
  }
  if (o.format == "mp4") return OutputKind::kMp4;
  if (o.format == "png") {
    if (!is_png_pattern(o.output)) {
      throw UsageError(fmt::format(
          "-o {}: a PNG sequence needs a pattern with one %d, %Nd or %0Nd (e.g. out/f_%04d.png)",
          o.output));
    }
    return OutputKind::kPngSequence;
  }
  if (ends_with(o.output, ".mp4")) return OutputKind::kMp4;
  if (is_png_pattern(o.output)) return OutputKind::kPngSequence;
  throw UsageError(fmt::format(
      "-o {}: cannot tell the output format; expected a name ending in .mp4, a PNG pattern like "
      "out/f_%04d.png, or --format mp4|png",
      o.output));
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
  FrameRange range;
  ClipPlan clip;  // frames to draw, fps, size, backend, anti-aliasing, overlays
  PngSettings png;
  Mp4Options mp4;
};

Plan make_plan(const RenderOptions& o, const LoadedScene& loaded) {
  Plan plan;
  plan.kind = output_kind(o);
  const Scene& scene = loaded.scene;
  plan.clip.fps = o.fps.value_or(scene.render.fps);
  const double duration = o.duration.value_or(scene.duration);
  const RunFrames run =
      run_frames(duration, o.duration ? "--duration" : "world.duration", plan.clip.fps,
                 o.fps ? "--fps" : "render.fps", loaded.world->settings().min_step);
  if (!run.error.empty()) throw UsageError(run.error);
  const std::size_t last = run.last;
  plan.range = frame_range(o.frames, last);
  if (plan.kind == OutputKind::kStrip) {
    plan.clip.frames = strip_frame_indices(plan.range.first, plan.range.last, o.strip);
  } else {
    for (std::size_t k = plan.range.first; k <= plan.range.last; ++k)
      plan.clip.frames.push_back(k);
  }
  std::tie(plan.clip.width, plan.clip.height) = frame_size(o.size, scene, plan.kind);
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
  if (plan.kind == OutputKind::kPngSequence) {
    for (const std::size_t frame : plan.clip.frames) {
      refuse_to_overwrite(format_frame_path(o.output, frame), o.overwrite);
    }
  } else {
    refuse_to_overwrite(o.output, o.overwrite);
  }
  return plan;
}

}  // namespace

int run_render(const RenderOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy, o.threads);
  if (!loaded) return kExitUsage;
  Plan plan;
  try {
    plan = make_plan(o, *loaded);
  } catch (const UsageError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }
  choose_rasteriser_threads(o.gl_threads);
  keep_frame_memory();
  const SigintGuard sigint;
  try {
    std::unique_ptr<FrameSink> sink;
    std::vector<Image> strip;
    if (plan.kind == OutputKind::kMp4) {
      quiet_ffmpeg_logs();
      sink = std::make_unique<Mp4Sink>(o.output, plan.clip.width, plan.clip.height, plan.mp4);
    } else if (plan.kind == OutputKind::kPngSequence) {
      sink = std::make_unique<PngSequenceSink>(o.output, plan.png, o.png_workers);
    } else {
      // The strip is written at the end: a folder that is not there fails now, not after
      // rendering.
      const std::filesystem::path folder = std::filesystem::path(o.output).parent_path();
      if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw SinkError(fmt::format("{}: No such file or directory (the folder of the strip)",
                                    folder.string()));
      }
    }
    Progress progress(static_cast<double>(plan.clip.frames.size()), stderr,
                      Progress::Unit::kFrames);
    std::size_t done = 0;
    const PipelineResult result = render_clip(
        *loaded, plan.clip,
        [&](const Image& image, std::size_t frame) {
          if (sink) {
            sink->write(image, frame);
          } else {
            strip.push_back(image);
          }
          progress.update(static_cast<double>(++done));
        },
        &SigintGuard::interrupted());
    progress.finish();
    if (sink) sink->close();
    if (plan.kind == OutputKind::kStrip && !result.interrupted) {
      write_png_file(
          o.output,
          compose_film_strip(strip, std::max(2, plan.clip.width / 160), {255, 255, 255, 255}),
          plan.png);
    }
    // The simulation runs on the pipeline's thread: its first crossing is told here, after it.
    CrossingWatch().check(*loaded->world, stderr);
    fmt::print(stderr, "{}: {} frame{} {} {} in {:.3g} s ({:.3g} frames/s)\n",
               result.interrupted ? "interrupted" : "done", result.frames,
               result.frames == 1 ? "" : "s",
               plan.kind == OutputKind::kStrip ? "in the strip" : "written to", o.output,
               progress.wall_seconds(),
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
