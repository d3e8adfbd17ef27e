// The scene renderer (scene_renderer.h): known bodies at known places give their colours well
// inside, the background well outside (concave notches included), the same pixels on both
// backends, and anti-aliased edges only where edges are.
#include "render/draw/scene_renderer.h"

#include <cstdint>
#include <memory>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

BodyLook look(std::vector<Vec2> control, const char* colour, double sigma, bool fixed = false) {
  BodyLook body{PeriodicBSpline(std::move(control)), {}, {}, *parse_hex_color(colour), fixed, 7};
  body.sigma.assign(body.curve.size(), sigma);
  body.lambda.assign(body.curve.size(), 0.9 * sigma);
  return body;
}

// A disk at (−1, 0), a box at (1, 0), and a "C" (a ring with a notch opening to the right) at
// (0, 0.2): the notch must stay background.
std::vector<BodyLook> known_bodies(double sigma) {
  std::vector<BodyLook> bodies;
  bodies.push_back(look(circle_control_points(0.45, 32), "#d04030", sigma));
  bodies.push_back(look(box_control_points(0.8, 0.6, 24), "#3050c0", sigma, true));
  std::vector<Vec2> c_shape;
  for (int i = 0; i < 40; ++i) {  // outer arc from 40° to 320°, inner arc back
    const double a = (40.0 + 280.0 * i / 39.0) * 3.14159265358979 / 180.0;
    c_shape.emplace_back(0.35 * std::cos(a), 0.35 * std::sin(a));
  }
  for (int i = 39; i >= 0; --i) {
    const double a = (40.0 + 280.0 * i / 39.0) * 3.14159265358979 / 180.0;
    c_shape.emplace_back(0.2 * std::cos(a), 0.2 * std::sin(a));
  }
  bodies.push_back(look(std::move(c_shape), "#30a050", sigma));
  return bodies;
}

FrameSnapshot known_frame() {
  FrameSnapshot frame;
  for (const Vec2& at : {Vec2(-1.0, 0.0), Vec2(1.0, 0.0), Vec2(0.0, 0.2)}) {
    frame.bodies.push_back(BodyPose{Transform2(0.0, at), Vec2::Zero(), 0.0, false});
  }
  return frame;
}

RenderSettings settings(AntiAliasing aa) {
  RenderSettings s;
  s.camera.center = Vec2(0.0, 0.0);
  s.camera.height = 1.8;  // 0.01 m per pixel
  s.camera.width_px = kWidth;
  s.camera.height_px = kHeight;
  s.background = *parse_hex_color("#f4f1ea");
  s.anti_aliasing = aa;
  return s;
}

Image render(GlBackend backend, AntiAliasing aa, double sigma = 0.0) {
  std::unique_ptr<GlContext> context = GlContext::create(backend, kWidth, kHeight);
  SceneRenderer renderer(*context, known_bodies(sigma), settings(aa));
  return renderer.render(known_frame());
}

// The pixel that shows world point p under settings(): x right, y up, rows from the top.
std::array<int, 3> at(const Image& image, const Vec2& p) {
  const int x = static_cast<int>(std::floor(p.x() / 0.01 + kWidth / 2.0));
  const int y = static_cast<int>(std::floor(kHeight / 2.0 - p.y() / 0.01));
  const std::uint8_t* px = image.pixel(x, y);
  return {px[0], px[1], px[2]};
}

TEST(SceneRenderer, BodiesHaveTheirColoursInsideAndTheBackgroundOutside) {
  for (const AntiAliasing aa : {AntiAliasing::kShader, AntiAliasing::kMsaa, AntiAliasing::kNone}) {
    SCOPED_TRACE(std::string(anti_aliasing_name(aa)));
    for (const double sigma : {0.0, 0.01}) {
      const Image image = render(GlBackend::kOsmesa, aa, sigma);
      ASSERT_EQ(image.width, kWidth);
      ASSERT_EQ(image.height, kHeight);
      using C = std::array<int, 3>;
      EXPECT_EQ(at(image, Vec2(-1.0, 0.0)), (C{0xd0, 0x40, 0x30}));         // disk centre
      EXPECT_EQ(at(image, Vec2(-1.2, 0.2)), (C{0xd0, 0x40, 0x30}));         // inside the disk
      EXPECT_EQ(at(image, Vec2(1.0, 0.0)), (C{0x30, 0x50, 0xc0}));          // box centre
      EXPECT_EQ(at(image, Vec2(1.3, -0.2)), (C{0x30, 0x50, 0xc0}));         // near its corner
      EXPECT_EQ(at(image, Vec2(-0.275, 0.2)), (C{0x30, 0xa0, 0x50}));       // C, left of ring
      EXPECT_EQ(at(image, Vec2(0.0, 0.2 + 0.275)), (C{0x30, 0xa0, 0x50}));  // C, top of ring
      EXPECT_EQ(at(image, Vec2(0.0, 0.2)), (C{0xf4, 0xf1, 0xea}));          // C, hollow centre
      EXPECT_EQ(at(image, Vec2(0.27, 0.2)), (C{0xf4, 0xf1, 0xea}));         // C, in the notch
      EXPECT_EQ(at(image, Vec2(0.0, -0.7)), (C{0xf4, 0xf1, 0xea}));         // below everything
      EXPECT_EQ(at(image, Vec2(-1.5, 0.8)), (C{0xf4, 0xf1, 0xea}));         // top-left corner
    }
  }
}

TEST(SceneRenderer, BothBackendsDrawTheSamePixels) {
  for (const AntiAliasing aa : {AntiAliasing::kShader, AntiAliasing::kMsaa}) {
    const Image osmesa = render(GlBackend::kOsmesa, aa, 0.01);
    const Image egl = render(GlBackend::kEgl, aa, 0.01);
    EXPECT_EQ(osmesa.rgba, egl.rgba) << anti_aliasing_name(aa);
  }
}

// Counts the distinct colours of a frame: without anti-aliasing only the fills, the outlines
// and the background; with it, edge pixels in between.
std::size_t distinct_colours(const Image& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    colours.insert(static_cast<std::uint32_t>(image.rgba[i]) << 16 |
                   static_cast<std::uint32_t>(image.rgba[i + 1]) << 8 | image.rgba[i + 2]);
  }
  return colours.size();
}

TEST(SceneRenderer, AntiAliasingBlendsEdgesOnly) {
  const std::size_t none = distinct_colours(render(GlBackend::kOsmesa, AntiAliasing::kNone));
  EXPECT_LE(none, 7u);  // background, 3 fills, 3 outlines
  EXPECT_GT(distinct_colours(render(GlBackend::kOsmesa, AntiAliasing::kShader)), 30u);
  // 4 samples give at most 5 shades per pair of colours.
  EXPECT_GT(distinct_colours(render(GlBackend::kOsmesa, AntiAliasing::kMsaa)), 15u);
}

TEST(SceneRenderer, MovesBodiesByTheirPlacement) {
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  SceneRenderer renderer(*context, known_bodies(0.0), settings(AntiAliasing::kShader));
  FrameSnapshot frame = known_frame();
  frame.bodies[0].placement = Transform2(0.3, Vec2(-1.0, -0.4));  // the disk moves down
  const Image image = renderer.render(frame);
  using C = std::array<int, 3>;
  EXPECT_EQ(at(image, Vec2(-1.0, -0.4)), (C{0xd0, 0x40, 0x30}));
  EXPECT_EQ(at(image, Vec2(-1.0, 0.3)), (C{0xf4, 0xf1, 0xea}));  // where its top was
  // A second frame with the original placement draws the original picture again.
  EXPECT_EQ(renderer.render(known_frame()).rgba,
            render(GlBackend::kOsmesa, AntiAliasing::kShader).rgba);
}

// A scene at rest is not drawn again, and what is read back is still the right picture; any
// change of placement draws.
TEST(SceneRenderer, UnchangedFramesAreReusedNotRedrawn) {
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  SceneRenderer renderer(*context, known_bodies(0.01), settings(AntiAliasing::kShader));
  const Image first = renderer.render(known_frame());
  FrameSnapshot same = known_frame();
  same.frame = 7;
  same.time = 0.25;
  EXPECT_EQ(renderer.render(same).rgba, first.rgba);
  EXPECT_EQ(renderer.frames_reused(), 1u);
  FrameSnapshot moved = known_frame();
  moved.bodies[2].placement = Transform2(1e-9, Vec2(0.0, 0.2));  // the smallest turn counts
  renderer.draw(moved);
  EXPECT_EQ(renderer.frames_reused(), 1u);
  EXPECT_EQ(renderer.render(known_frame()).rgba, first.rgba);
  EXPECT_EQ(renderer.frames_reused(), 1u);
}

TEST(SceneRenderer, RejectsASnapshotOfAnotherScene) {
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  SceneRenderer renderer(*context, known_bodies(0.0), settings(AntiAliasing::kShader));
  FrameSnapshot frame = known_frame();
  frame.bodies.pop_back();
  EXPECT_THROW(renderer.draw(frame), std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
