// Rendering figure12a (the quick start's scene: eight rocks falling into a container, at rest
// from about 2.5 s), measured against baselines in the same run (bench/ratio_reporter.h):
//
//   frame/<aa>/<height>     rendering alone (draw + read back) of the clip's frames, per frame,
//                           against frame/baseline: a bare clear and read back of the same size
//                           into the same reused image (the least any GL frame costs here).
//                           Counter edge_error: the mean absolute difference (0..255 a channel)
//                           on edge pixels from a 16× supersampled reference (the same frame
//                           drawn 4× larger without anti-aliasing, same detail, averaged over
//                           4×4 blocks): the quality side of the anti-aliasing comparison.
//   mp4/rugosim/<height>    `rugosim render figure12a.json -o clip.mp4` end to end (load,
//                           simulate, render, encode the whole 5 s clip, as the quick start
//                           does), against mp4/baseline: the `ffmpeg` command encoding the same
//                           frames from raw RGBA with the same settings (libx264, crf 18,
//                           preset medium, a keyframe a second, yuv420p, fragmented MP4).
//                           Ratio ≤ 1.11 means ≥ 0.9 of ffmpeg's throughput. ffmpeg runs with
//                           the malloc thresholds rugosim sets for itself (GLIBC_TUNABLES;
//                           render/app/frame_memory.h): without them x264's buffers are mapped
//                           and zeroed again and again on some runs (15-20% more CPU time), so
//                           the ratio would credit rugosim with glibc's behaviour.
//   png/rugosim/<height>    `rugosim render` to a PNG sequence, against png/baseline: `ffmpeg`
//                           writing the same frames as PNGs from raw RGBA (its defaults).
//   gif/rugosim/<height>    `rugosim render -o clip.gif`, against gif/baseline: `ffmpeg` making
//                           the same GIF from raw RGBA with the same filters (alpha dropped,
//                           palettegen over the clip, paletteuse with sierra2_4a dithering in
//                           changed rectangles) and muxer options.
//   webm/rugosim/<height>   `rugosim render -o clip.webm`, against webm/baseline: `ffmpeg`
//                           encoding the same frames with the same settings (BT.709 limited
//                           range yuv420p, libvpx-vp9 crf 24, deadline good, cpu-used 4,
//                           row-mt). Ratio ≤ 1.11 again means ≥ 0.9 of ffmpeg's throughput.
//
// Counters: frames_per_s for every run. The raw frames for ffmpeg are made once, by the same
// renderer, in a temporary folder. The frame benchmarks cycle through the clip's first 90
// frames (3 s), where the rocks move: the frames at rest would only measure the read back.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include "engine/dynamics/frame_snapshot.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "ratio_reporter.h"
#include "render/app/render_scene.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"

namespace rugosim {
namespace {

constexpr std::size_t kMovingFrames = 90;  // 3 s at 30 fps: the rocks falling and settling

const std::string kScene = std::string(RUGOSIM_SOURCE_DIR) + "/scenes/figure12a.json";
const std::filesystem::path kWork = std::filesystem::temp_directory_path() / "rugosim_bench_render";

int width_for(std::int64_t height) {
  return static_cast<int>(height * 16 / 9);
}

struct Clip {
  Scene scene;
  std::unique_ptr<World> world;
  std::vector<FrameSnapshot> frames;  // every frame of the clip, as `rugosim render` makes it
};

// The scene simulated once; every benchmark draws the same snapshots.
const Clip& clip() {
  static const Clip loaded = [] {
    Clip c;
    c.scene = load_scene_file(kScene).scene;
    SceneWorld built = build_world(c.scene, kScene);
    c.world = std::move(built.world);
    const double fps = c.scene.render.fps;
    // The frames `render` draws: k / fps for k = 0 .. ⌊duration × fps⌋.
    const auto count = static_cast<std::size_t>(std::floor(c.scene.duration * fps + 1e-9)) + 1;
    for (std::size_t k = 0; k < count; ++k) {
      if (k > 0) c.world->advance_to(static_cast<double>(k) / fps);
      c.frames.push_back(take_snapshot(*c.world, k));
      c.world->clear_events();
    }
    return c;
  }();
  return loaded;
}

RenderSettings settings_for(const Clip& c, int width, int height, AntiAliasing aa) {
  RenderSettings s;
  s.camera = app::fit_clip_camera(*c.world, c.frames, width, height);
  s.background = app::scene_background(c.scene);
  s.anti_aliasing = aa;
  return s;
}

void report_fps(benchmark::State& state, std::size_t frames_per_iteration) {
  state.counters["frames_per_s"] = benchmark::Counter(
      static_cast<double>(frames_per_iteration), benchmark::Counter::kIsIterationInvariantRate);
}

void frame_baseline(benchmark::State& state) {
  const int height = static_cast<int>(state.range(0));
  std::unique_ptr<GlContext> context =
      GlContext::create(GlBackend::kOsmesa, width_for(height), height);
  const GlApi& gl = context->gl();
  std::vector<std::uint8_t> pixels(Image::bytes(context->width(), context->height()));
  for (auto _ : state) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, context->framebuffer());
    gl.ClearColor(0.9f, 0.9f, 0.9f, 1.f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, context->width(), context->height(), GL_RGBA, GL_UNSIGNED_BYTE,
                  pixels.data());
    benchmark::DoNotOptimize(pixels.data());
  }
  report_fps(state, 1);
}

Image draw_frame(int width, int height, AntiAliasing aa, double spacing_px, std::size_t k) {
  const Clip& c = clip();
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, width, height);
  RenderSettings settings = settings_for(c, width, height, aa);
  settings.detail.spacing_px = spacing_px;
  SceneRenderer renderer(*context, app::body_looks(c.scene, *c.world), settings);
  return renderer.render(c.frames[k]);
}

// Mean absolute channel difference from the supersampled reference over the pixels whose 4×4
// reference block is not one flat colour (the edges: elsewhere every method is exact).
double edge_error(const Image& image) {
  static std::map<int, Image> references;
  const int w = image.width, h = image.height;
  if (references.count(h) == 0) {
    references[h] = draw_frame(4 * w, 4 * h, AntiAliasing::kNone, 4 * 1.5, kMovingFrames / 2);
  }
  const Image& big = references[h];
  double sum = 0.0;
  std::size_t count = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double mean[3] = {0, 0, 0};
      bool flat = true;
      const std::uint8_t* first = big.pixel(4 * x, 4 * y);
      for (int dy = 0; dy < 4; ++dy) {
        for (int dx = 0; dx < 4; ++dx) {
          const std::uint8_t* p = big.pixel(4 * x + dx, 4 * y + dy);
          for (int c = 0; c < 3; ++c) {
            mean[c] += p[c] / 16.0;
            flat = flat && p[c] == first[c];
          }
        }
      }
      if (flat) continue;
      const std::uint8_t* q = image.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        sum += std::abs(q[c] - mean[c]);
      count += 3;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

void frame_render(benchmark::State& state, AntiAliasing aa) {
  const Clip& c = clip();
  const int height = static_cast<int>(state.range(0));
  std::unique_ptr<GlContext> context =
      GlContext::create(GlBackend::kOsmesa, width_for(height), height);
  SceneRenderer renderer(*context, app::body_looks(c.scene, *c.world),
                         settings_for(c, width_for(height), height, aa));
  Image image;
  std::size_t k = 0;
  for (auto _ : state) {
    renderer.draw(c.frames[k++ % kMovingFrames]);
    renderer.read(image);
    benchmark::DoNotOptimize(image.rgba.data());
  }
  report_fps(state, 1);
  state.counters["edge_error"] = edge_error(renderer.render(c.frames[kMovingFrames / 2]));
}

// The clip's frames as raw RGBA for ffmpeg, made once per size.
std::string raw_frames(int width, int height) {
  const std::filesystem::path path = kWork / fmt::format("frames_{}x{}.rgba", width, height);
  if (std::filesystem::exists(path)) return path.string();
  std::filesystem::create_directories(kWork);
  const Clip& c = clip();
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, width, height);
  SceneRenderer renderer(*context, app::body_looks(c.scene, *c.world),
                         settings_for(c, width, height, AntiAliasing::kShader));
  std::ofstream out(path, std::ios::binary);
  Image image;
  for (const FrameSnapshot& frame : c.frames) {
    renderer.draw(frame);
    renderer.read(image);
    out.write(reinterpret_cast<const char*>(image.rgba.data()),
              static_cast<std::streamsize>(image.rgba.size()));
  }
  return path.string();
}

void run_command(benchmark::State& state, const std::string& command) {
  if (std::system(command.c_str()) != 0) state.SkipWithError(("failed: " + command).c_str());
}

// What the ffmpeg command writes for each family: the encoder's settings and the output.
std::string ffmpeg_output(const std::string& family) {
  const std::string work = kWork.string();
  if (family == "png") return fmt::format("{}/ffmpeg_%04d.png", work);
  if (family == "gif") {
    return fmt::format(
        "-filter_complex \"format=rgb24,split[frames][stats];[stats]palettegen=stats_mode=full:"
        "reserve_transparent=1[palette];[frames][palette]paletteuse=dither=sierra2_4a:diff_mode="
        "rectangle:alpha_threshold=128\" -loop 0 {}/ffmpeg.gif",
        work);
  }
  if (family == "webm") {
    return fmt::format(
        "-vf format=rgb24,scale=out_color_matrix=bt709:out_range=tv,format=yuv420p "
        "-c:v libvpx-vp9 -crf 24 -b:v 0 -deadline good -cpu-used 4 -row-mt 1 "
        "-color_range tv -colorspace bt709 -color_primaries bt709 -color_trc bt709 "
        "{}/ffmpeg.webm",
        work);
  }
  return fmt::format(
      "-c:v libx264 -crf 18 -preset medium -g 30 -pix_fmt yuv420p "
      "-movflags frag_keyframe+empty_moov+default_base_moof {}/ffmpeg.mp4",
      work);
}

void ffmpeg_encode(benchmark::State& state, const std::string& family) {
  if (std::system("ffmpeg -version > /dev/null 2>&1") != 0) {
    state.SkipWithError("ffmpeg is not on PATH (Debian package ffmpeg)");
    return;
  }
  const int height = static_cast<int>(state.range(0));
  const int width = width_for(height);
  const std::string raw = raw_frames(width, height);
  const std::string input = fmt::format(
      "GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=268435456 "
      "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s {}x{} -r 30 -i {} ",
      width, height, raw);
  const std::string output = ffmpeg_output(family);
  for (auto _ : state)
    run_command(state, input + output);
  report_fps(state, clip().frames.size());
}

void rugosim_render(benchmark::State& state, const std::string& family) {
  const int height = static_cast<int>(state.range(0));
  const std::string out = family == "png" ? kWork.string() + "/rugosim_%04d.png"
                                          : kWork.string() + "/rugosim." + family;
  std::filesystem::create_directories(kWork);
  const std::string command = fmt::format("{} render {} -o {} -y --size {}x{} 2> /dev/null",
                                          RUGOSIM_PROGRAM, kScene, out, width_for(height), height);
  for (auto _ : state)
    run_command(state, command);
  report_fps(state, clip().frames.size());
}

void register_all() {
  for (const std::int64_t height : {720, 1080}) {
    benchmark::RegisterBenchmark("frame/baseline", frame_baseline)
        ->Arg(height)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    for (const AntiAliasing aa :
         {AntiAliasing::kShader, AntiAliasing::kMsaa, AntiAliasing::kNone}) {
      benchmark::RegisterBenchmark(fmt::format("frame/{}", anti_aliasing_name(aa)).c_str(),
                                   [aa](benchmark::State& s) { frame_render(s, aa); })
          ->Arg(height)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
    for (const std::string family : {"mp4", "png", "gif", "webm"}) {
      benchmark::RegisterBenchmark((family + "/baseline").c_str(),
                                   [family](benchmark::State& s) { ffmpeg_encode(s, family); })
          ->Arg(height)
          ->Iterations(1)
          ->Repetitions(5)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark((family + "/rugosim").c_str(),
                                   [family](benchmark::State& s) { rugosim_render(s, family); })
          ->Arg(height)
          ->Iterations(1)
          ->Repetitions(5)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  rugosim::register_all();
  const int code = rugosim::bench::run_with_ratios(argc, argv);
  std::filesystem::remove_all(rugosim::kWork);
  return code;
}
