#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

#include <fmt/core.h>

#include "engine/dynamics/frame_snapshot.h"
#include "render/app/commands.h"
#include "render/app/progress.h"
#include "render/app/render_scene.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "render/pipeline/render_pipeline.h"
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

// The renderer of the render thread: its own GL context and scene renderer.
class ContextRenderer final : public FrameRenderer {
 public:
  ContextRenderer(std::unique_ptr<GlContext> context, std::vector<BodyLook> looks,
                  const RenderSettings& settings)
      : context_(std::move(context)), renderer_(*context_, std::move(looks), settings) {}
  void render(const FrameSnapshot& frame, Image& image) override {
    renderer_.draw(frame);
    renderer_.read(image);
  }

 private:
  std::unique_ptr<GlContext> context_;
  SceneRenderer renderer_;
};

struct Plan {
  OutputKind kind = OutputKind::kMp4;
  FrameRange range;
  std::vector<std::size_t> frames;  // to draw, in order
  double fps = 30.0;
  int width = 0;
  int height = 0;
  GlBackend backend = GlBackend::kOsmesa;
  AntiAliasing anti_aliasing = AntiAliasing::kShader;
  Overlays overlays;
  PngSettings png;
  Mp4Options mp4;
};

Plan make_plan(const RenderOptions& o, const LoadedScene& loaded) {
  Plan plan;
  plan.kind = output_kind(o);
  const Scene& scene = loaded.scene;
  plan.fps = o.fps.value_or(scene.render.fps);
  const double duration = o.duration.value_or(scene.duration);
  const auto last = static_cast<std::size_t>(std::floor(duration * plan.fps + 1e-9));
  plan.range = frame_range(o.frames, last);
  if (plan.kind == OutputKind::kStrip) {
    plan.frames = strip_frame_indices(plan.range.first, plan.range.last, o.strip);
  } else {
    for (std::size_t k = plan.range.first; k <= plan.range.last; ++k)
      plan.frames.push_back(k);
  }
  std::tie(plan.width, plan.height) = frame_size(o.size, scene, plan.kind);
  const std::optional<GlBackend> backend = parse_gl_backend(o.backend);
  if (!backend) throw UsageError("--backend: expected osmesa or egl, got \"" + o.backend + "\"");
  plan.backend = *backend;
  const std::optional<AntiAliasing> aa = parse_anti_aliasing(o.anti_aliasing);
  if (!aa) {
    throw UsageError("--aa: expected shader, msaa or none, got \"" + o.anti_aliasing + "\"");
  }
  plan.anti_aliasing = *aa;
  std::string unknown;
  const std::optional<Overlays> overlays =
      parse_overlays(o.overlays.value_or(scene.render.overlays), &unknown);
  if (!overlays) {
    throw UsageError("--overlay: unknown overlay \"" + unknown +
                     "\"; expected rugosity, contacts or velocity");
  }
  plan.overlays = *overlays;
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
  plan.mp4.fps = plan.fps;
  plan.mp4.crf = o.crf;
  plan.mp4.preset = o.preset;
  if (plan.kind == OutputKind::kPngSequence) {
    for (const std::size_t frame : plan.frames) {
      refuse_to_overwrite(format_frame_path(o.output, frame), o.overwrite);
    }
  } else {
    refuse_to_overwrite(o.output, o.overwrite);
  }
  return plan;
}

// The snapshots of the clip, made on the simulation thread. With an explicit camera each frame
// is simulated when asked for. With "auto" the whole clip is simulated at the first call (the
// snapshots are small), the camera that frames every body over all of it is published to the
// render thread, and the stored snapshots are handed out.
class ClipSource {
 public:
  ClipSource(World& world, const Plan& plan, std::optional<Camera> camera)
      : world_(world), plan_(plan), automatic_(!camera) {
    if (camera) camera_.set_value(camera);
  }

  std::optional<FrameSnapshot> next() {
    if (!automatic_) return simulate_next();
    if (!simulated_) simulate_clip();
    if (handed_ >= clip_.size()) return std::nullopt;
    return std::move(clip_[handed_++]);
  }

  // Blocks until the camera is known; nullopt when the simulation was interrupted first.
  std::optional<Camera> camera() { return camera_future_.get(); }

 private:
  // The World passes through every frame time of the clip, drawn or not: a step ends at each
  // time it is asked for, so stopping only at the drawn frames would give another trajectory
  // (a strip's frames or a --frames range must look exactly as in the whole clip, and as in
  // `simulate` at the same fps). The events kept are those since the previous frame time.
  std::optional<FrameSnapshot> simulate_next() {
    if (next_ >= plan_.frames.size()) return std::nullopt;
    const std::size_t frame = plan_.frames[next_++];
    for (; reached_ < frame; ++reached_) {
      world_.clear_events();
      world_.advance_to(static_cast<double>(reached_ + 1) / plan_.fps);
    }
    FrameSnapshot snapshot = take_snapshot(world_, frame);
    world_.clear_events();
    return snapshot;
  }

  void simulate_clip() {
    simulated_ = true;
    try {
      while (std::optional<FrameSnapshot> snapshot = simulate_next()) {
        if (SigintGuard::interrupted()) {
          clip_.clear();
          camera_.set_value(std::nullopt);
          return;
        }
        clip_.push_back(std::move(*snapshot));
      }
      camera_.set_value(fit_clip_camera(world_, clip_, plan_.width, plan_.height));
    } catch (...) {
      camera_.set_exception(std::current_exception());
      throw;
    }
  }

  World& world_;
  const Plan& plan_;
  bool automatic_;
  std::promise<std::optional<Camera>> camera_;
  std::future<std::optional<Camera>> camera_future_ = camera_.get_future();
  std::size_t next_ = 0;
  std::size_t reached_ = 0;  // the frame whose time the World is at
  bool simulated_ = false;
  std::vector<FrameSnapshot> clip_;
  std::size_t handed_ = 0;
};

// llvmpipe's rasteriser threads, read by Mesa when the first context starts. By default none:
// the render thread rasterises alone, because the cores are better spent on the encoder (x264's
// threads, the PNG workers) and the simulation; measured on 2 cores (bench/render_bench.cpp),
// 90 frames of figure12a to MP4 at 720p take 1.1–1.2 s this way against 1.6–1.7 s with
// llvmpipe's default of one thread per core. An LP_NUM_THREADS the user set is kept.
void choose_rasteriser_threads(const std::optional<int>& threads) {
  if (threads) {
    ::setenv("LP_NUM_THREADS", std::to_string(*threads).c_str(), 1);
  } else {
    ::setenv("LP_NUM_THREADS", "0", 0);
  }
}

}  // namespace

int run_render(const RenderOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy);
  if (!loaded) return kExitUsage;
  Plan plan;
  try {
    plan = make_plan(o, *loaded);
  } catch (const UsageError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }
  World& world = *loaded->world;
  choose_rasteriser_threads(o.gl_threads);
  const SigintGuard sigint;
  try {
    RenderSettings settings;
    settings.background = *parse_hex_color(loaded->scene.render.background);
    settings.anti_aliasing = plan.anti_aliasing;
    settings.overlays = plan.overlays;
    ClipSource source(world, plan, scene_camera(loaded->scene, plan.width, plan.height));

    std::unique_ptr<FrameSink> sink;
    std::vector<Image> strip;
    if (plan.kind == OutputKind::kMp4) {
      quiet_ffmpeg_logs();
      sink = std::make_unique<Mp4Sink>(o.output, plan.width, plan.height, plan.mp4);
    } else if (plan.kind == OutputKind::kPngSequence) {
      sink = std::make_unique<PngSequenceSink>(o.output, plan.png);
    } else {
      // The strip is written at the end: a folder that is not there fails now, not after
      // rendering.
      const std::filesystem::path folder = std::filesystem::path(o.output).parent_path();
      if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw SinkError(fmt::format("{}: No such file or directory (the folder of the strip)",
                                    folder.string()));
      }
    }

    PipelineStages stages;
    stages.next_snapshot = [&] { return source.next(); };
    const std::vector<BodyLook> looks = body_looks(loaded->scene, world);
    stages.make_renderer = [&]() -> std::unique_ptr<FrameRenderer> {
      // The context starts (Mesa, shaders) while the simulation runs; the meshes wait for the
      // camera, whose pixel size sets their detail.
      std::unique_ptr<GlContext> context = GlContext::create(plan.backend, plan.width, plan.height);
      const std::optional<Camera> camera = source.camera();
      if (!camera) return nullptr;  // interrupted before the clip was simulated
      RenderSettings with_camera = settings;
      with_camera.camera = *camera;
      return std::make_unique<ContextRenderer>(std::move(context), looks, with_camera);
    };
    Progress progress(static_cast<double>(plan.frames.size()), stderr, Progress::Unit::kFrames);
    std::size_t done = 0;
    stages.consume = [&](const Image& image, std::size_t frame) {
      if (sink) {
        sink->write(image, frame);
      } else {
        strip.push_back(image);
      }
      progress.update(static_cast<double>(++done));
    };
    stages.interrupted = &SigintGuard::interrupted();
    const PipelineResult result = run_pipeline(stages);
    progress.finish();
    if (sink) sink->close();
    if (plan.kind == OutputKind::kStrip && !result.interrupted) {
      write_png_file(o.output,
                     compose_film_strip(strip, std::max(2, plan.width / 160), {255, 255, 255, 255}),
                     plan.png);
    }
    fmt::print(stderr, "{}: {} frame{} {} {} in {:.3g} s ({:.3g} frames/s)\n",
               result.interrupted ? "interrupted" : "done", result.frames,
               result.frames == 1 ? "" : "s",
               plan.kind == OutputKind::kStrip ? "in the strip" : "written to", o.output,
               progress.wall_seconds(),
               static_cast<double>(result.frames) / std::max(progress.wall_seconds(), 1e-9));
    return result.interrupted ? kExitInterrupted : kExitOk;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
