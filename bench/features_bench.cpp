// "Only what the scene requires" (issue 8): what a scene does not use costs it nothing. Each
// family's baseline is the scene as it is; the variants add the work it would have paid for
// without the shortcut, so a ratio above 1 is what the shortcut saves:
//
//   tolerance/<variant>   a disk sliding and rolling on a block for 1 s. Baseline: σ the same
//                         on every segment (homogeneous: λ(t) is a constant, the interpolating
//                         cubic is skipped). "varying": one segment of each body off by 1e-12
//                         of σ, which makes no difference to the motion but makes every λ(t)
//                         an interpolation.
//   sleep/<variant>       a settled pile of 50 bodies advanced by 1 s. Baseline: asleep (the
//                         World jumps to the target time). "off": the same pile settled with
//                         sleeping off, every body stepped and tested.
//   overlays/<variant>    drawing the moving part of figure12a at 1280×720 (90 frames).
//                         Baseline: no overlays. "rugosity": outlines coloured by λ (same
//                         geometry); "contacts_velocity": points, impulses and velocity arrows
//                         built on the CPU every frame (and every frame drawn whole).
//   static/<variant>      the same frames. Baseline: incremental redraw (a still floor and
//                         walls are not drawn again). "full_redraw": every frame drawn whole.
//   text/<variant>        the same frames read back, with the frame text painter the render
//                         command uses. Baseline: no text asked for (the painter opens no
//                         font and returns at once). "no_painter": no painter at all, so a
//                         ratio of 1 shows that a scene without text pays nothing for it;
//                         "all": a title, a caption, the clock and a scale bar, what text costs.
//   presets/<variant>     simulating figure12a (5 s) at each accuracy preset, against
//                         precise as the baseline (issue 8's target: draft at most 0.1 of it).
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/dynamics/frame_snapshot.h"
#include "engine/geometry/shapes.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "ratio_reporter.h"
#include "render/app/render_scene.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "render/text/frame_text.h"
#include "support/pile_scene.h"

namespace rugosim {
namespace {

// ---- tolerance interpolation -------------------------------------------------------------

World sliding_disk(bool homogeneous) {
  WorldSettings settings;
  settings.record_events = false;
  World world(settings);
  auto sigmas = [&](std::size_t n, double sigma) {
    std::vector<double> s(n, sigma);
    if (!homogeneous) s[n / 2] *= 1.0 + 1e-12;
    return s;
  };
  RigidBodyDesc block;
  block.control_points = box_control_points(8.0, 0.4, 64);
  block.sigma = sigmas(64, 0.0033333333333333335);
  block.material.lambda_min = 0.001;
  block.material.restitution = 0.0;
  block.fixed = true;
  block.position = Vec2(0.0, -0.2);
  world.add_body(RigidBody(block), "block");
  RigidBodyDesc disk;
  disk.control_points = circle_control_points(0.25, 64);
  disk.sigma = sigmas(64, 0.001);
  disk.material.restitution = 0.0;
  disk.position = Vec2(-3.0, 0.2515);
  disk.velocity = Vec2(2.0, 0.0);
  world.add_body(RigidBody(disk), "disk");
  return world;
}

void tolerance(benchmark::State& state, bool homogeneous) {
  for (auto _ : state) {
    state.PauseTiming();
    World world = sliding_disk(homogeneous);
    state.ResumeTiming();
    world.advance_to(1.0);
    benchmark::DoNotOptimize(world.body(1).state());
  }
}

// ---- sleeping ------------------------------------------------------------------------------

const World& settled_pile(bool sleeping) {
  static std::unique_ptr<World> piles[2];
  std::unique_ptr<World>& pile = piles[sleeping ? 1 : 0];
  if (!pile) {
    testing::PileSpec spec;
    spec.bodies = 50;
    WorldSettings settings;
    settings.record_events = false;
    settings.sleep.enabled = sleeping;
    pile = std::make_unique<World>(settings);
    for (const testing::PileBody& b : testing::pile_scene(spec))
      pile->add_body(RigidBody(b.desc), b.name);
    pile->advance_to(4.0);
  }
  return *pile;
}

void sleep(benchmark::State& state, bool sleeping) {
  const World& settled = settled_pile(sleeping);
  for (auto _ : state) {
    state.PauseTiming();
    World world = settled;
    state.ResumeTiming();
    world.advance_to(settled.time() + 1.0);
    benchmark::DoNotOptimize(world.body(1).state());
  }
}

// ---- accuracy presets ----------------------------------------------------------------------

void preset(benchmark::State& state, const std::string& name) {
  const std::string path = std::string(RUGOSIM_SOURCE_DIR) + "/scenes/figure12a.json";
  Scene scene = load_scene_file(path).scene;
  scene.accuracy = AccuracySpec{name, {}};
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<World> world = std::move(build_world(scene, path).world);
    state.ResumeTiming();
    // Frame by frame, as simulate and render step it (each frame time ends a step).
    const auto frames = static_cast<int>(std::floor(scene.duration * scene.render.fps + 1e-9));
    for (int k = 1; k <= frames; ++k) {
      world->advance_to(k / scene.render.fps);
      world->clear_events();
    }
    benchmark::DoNotOptimize(world->body(3).state());
  }
}

// ---- drawing -------------------------------------------------------------------------------

constexpr std::size_t kFrames = 90;

struct Clip {
  Scene scene;
  std::unique_ptr<World> world;
  std::vector<FrameSnapshot> frames;
};

const Clip& figure12a() {
  static const Clip clip = [] {
    Clip c;
    const std::string path = std::string(RUGOSIM_SOURCE_DIR) + "/scenes/figure12a.json";
    c.scene = load_scene_file(path).scene;
    c.world = std::move(build_world(c.scene, path).world);
    for (std::size_t k = 0; k < kFrames; ++k) {
      if (k > 0) c.world->advance_to(static_cast<double>(k) / c.scene.render.fps);
      c.frames.push_back(take_snapshot(*c.world, k));
      c.world->clear_events();
    }
    return c;
  }();
  return clip;
}

// `text`: painted over each frame read back (nullopt: no painter at all).
void draw(benchmark::State& state, Overlays overlays, bool incremental,
          std::optional<FrameText> text) {
  const Clip& c = figure12a();
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, 1280, 720);
  RenderSettings settings;
  settings.camera = app::fit_clip_camera(*c.world, c.frames, 1280, 720);
  settings.background = *parse_hex_color(c.scene.render.background);
  settings.overlays = overlays;
  settings.incremental = incremental;
  SceneRenderer renderer(*context, app::body_looks(c.scene, *c.world), settings);
  std::optional<FrameTextPainter> painter;
  if (text) painter.emplace(*text);
  Image image;
  std::size_t k = 0;
  for (auto _ : state) {
    const FrameSnapshot& frame = c.frames[k++ % kFrames];
    renderer.draw(frame);
    renderer.read(image);
    if (painter) painter->paint(image, frame.time, settings.camera.pixel_size());
    benchmark::DoNotOptimize(image.rgba.data());
  }
}

FrameText all_text() {
  FrameText text;
  text.title = "Eight rough rocks";
  text.caption = "rugosim: figure 12a of the paper";
  text.clock = true;
  text.scale_bar = true;
  return text;
}

void register_all() {
  using benchmark::RegisterBenchmark;
  RegisterBenchmark("tolerance/baseline", tolerance, true)->Unit(benchmark::kMillisecond);
  RegisterBenchmark("tolerance/varying", tolerance, false)->Unit(benchmark::kMillisecond);
  RegisterBenchmark("sleep/baseline", sleep, true)->Unit(benchmark::kMicrosecond);
  RegisterBenchmark("sleep/off", sleep, false)->Unit(benchmark::kMicrosecond);
  RegisterBenchmark("overlays/baseline", draw, Overlays{}, true, std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("overlays/rugosity", draw, Overlays{true, false, false}, true,
                    std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("overlays/contacts_velocity", draw, Overlays{false, true, true}, true,
                    std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("static/baseline", draw, Overlays{}, true, std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("static/full_redraw", draw, Overlays{}, false, std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("text/baseline", draw, Overlays{}, true, std::optional<FrameText>(FrameText{}))
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("text/no_painter", draw, Overlays{}, true, std::optional<FrameText>())
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("text/all", draw, Overlays{}, true, std::optional<FrameText>(all_text()))
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("presets/baseline", preset, std::string("precise"))
      ->Unit(benchmark::kMillisecond);
  RegisterBenchmark("presets/normal", preset, std::string("normal"))->Unit(benchmark::kMillisecond);
  RegisterBenchmark("presets/draft", preset, std::string("draft"))->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace rugosim

int main(int argc, char** argv) {
  rugosim::register_all();
  return rugosim::bench::run_with_ratios(argc, argv);
}
