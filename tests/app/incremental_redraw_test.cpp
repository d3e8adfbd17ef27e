// The renderer's incremental redraw on the built-in scenes as `rugosim render` draws them (the
// scene's looks and automatic camera, every frame time of the clip): each frame is bit for bit
// the frame a full redraw gives, and after the first most frames are redrawn only in part.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"
#include "render/app/render_scene.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "support/program_under_test.h"
#include "support/same_frames.h"

namespace rugosim {
namespace {

void expect_incremental_equals_full(const std::string& name, bool rugosity) {
  const std::string path = (testing::source_dir() / "scenes" / (name + ".json")).string();
  const Scene scene = load_scene_file(path).scene;
  SceneWorld built = build_world(scene, path);
  World& world = *built.world;
  const std::vector<BodyLook> looks = app::body_looks(scene, world);
  std::vector<FrameSnapshot> clip;
  const double fps = scene.render.fps;
  const auto last = static_cast<std::size_t>(std::floor(scene.duration * fps + 1e-9));
  for (std::size_t k = 0; k <= last; ++k) {
    if (k > 0) world.advance_to(static_cast<double>(k) / fps);
    clip.push_back(take_snapshot(world, k));
    world.clear_events();
  }
  constexpr int kWidth = 640, kHeight = 360;
  RenderSettings settings;
  settings.camera = app::fit_clip_camera(world, clip, kWidth, kHeight);
  settings.background = *parse_hex_color(scene.render.background);
  settings.overlays.rugosity = rugosity;
  std::unique_ptr<GlContext> a = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  std::unique_ptr<GlContext> b = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  settings.incremental = true;
  SceneRenderer incremental(*a, looks, settings);
  settings.incremental = false;
  SceneRenderer full(*b, looks, settings);
  ASSERT_EQ(testing::first_different_frame(incremental, full, clip), std::nullopt) << name;
  const std::size_t drawn = clip.size() - incremental.frames_reused();
  EXPECT_GT(incremental.frames_partial(), drawn / 2) << name;
}

TEST(IncrementalRedraw, Figure12aFramesAreThoseOfAFullRedraw) {
  expect_incremental_equals_full("figure12a", false);
}

TEST(IncrementalRedraw, Figure12bFramesWithTheRugosityOverlayAreThoseOfAFullRedraw) {
  expect_incremental_equals_full("figure12b", true);
}

TEST(IncrementalRedraw, Figure09FramesAreThoseOfAFullRedraw) {
  expect_incremental_equals_full("figure09_type2_type3", false);
}

}  // namespace
}  // namespace rugosim
