// The scene renderer (scene_renderer.h): known bodies at known places give their colours well
// inside, the background well outside (concave notches included), the same pixels on both
// backends, and anti-aliased edges only where edges are.
#include "render/draw/scene_renderer.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/geometry/shapes.h"
#include "support/same_frames.h"

namespace rugosim {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

BodyLook look(std::vector<Vec2> control, const char* colour, double sigma, bool fixed = false) {
  BodyLook body{PeriodicBSpline(std::move(control)),
                {},
                {},
                *parse_hex_color(colour),
                fixed,
                7,
                std::nullopt};
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

// A scene for the incremental redraw: a fixed floor and walls, rough blobs, a disk, the "C"
// and a thin sliver, at 640×360 (0.005 m per pixel).
std::vector<BodyLook> busy_bodies() {
  std::vector<BodyLook> bodies;
  bodies.push_back(look(box_control_points(3.0, 0.1, 48), "#807060", 0.004, true));
  bodies.push_back(look(box_control_points(0.1, 1.5, 24), "#706050", 0.003, true));
  bodies.push_back(look(box_control_points(0.1, 1.5, 24), "#706050", 0.003, true));
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    bodies.push_back(look(blob_control_points(0.12, 0.45, 24, seed),
                          seed % 2 ? "#c05030" : "#3070b0", 0.002 * static_cast<double>(seed)));
  }
  bodies.push_back(look(circle_control_points(0.1, 16), "#d0a020", 0.0));
  bodies.push_back(known_bodies(0.003)[2]);
  bodies.push_back(look(box_control_points(0.6, 0.01, 16), "#202020", 0.0005));
  return bodies;
}

RenderSettings busy_settings(AntiAliasing aa, bool incremental, bool rugosity) {
  RenderSettings s = settings(aa);
  s.camera.height = 1.8;
  s.camera.width_px = 640;
  s.camera.height_px = 360;
  s.incremental = incremental;
  s.overlays.rugosity = rugosity;
  return s;
}

// A seeded random clip: most frames move a few bodies a little (falling, turning), some move
// one body far or off the frame and back, some repeat the frame before; the fixed bodies never
// move.
std::vector<FrameSnapshot> busy_clip(std::size_t bodies, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  FrameSnapshot frame;
  frame.bodies.push_back(BodyPose{Transform2(0.0, Vec2(0.0, -0.8)), Vec2::Zero(), 0.0, false});
  frame.bodies.push_back(BodyPose{Transform2(0.0, Vec2(-1.5, -0.1)), Vec2::Zero(), 0.0, false});
  frame.bodies.push_back(BodyPose{Transform2(0.0, Vec2(1.5, -0.1)), Vec2::Zero(), 0.0, false});
  while (frame.bodies.size() < bodies) {
    frame.bodies.push_back(BodyPose{
        Transform2(6.28 * unit(random), Vec2(2.6 * unit(random) - 1.3, 1.2 * unit(random) - 0.6)),
        Vec2::Zero(), 0.0, false});
  }
  std::vector<FrameSnapshot> clip{frame};
  for (std::size_t k = 1; k < 80; ++k) {
    frame.frame = k;
    const double kind = unit(random);
    if (kind < 0.1) {
      // the same picture again
    } else if (kind < 0.2) {
      const auto movable = static_cast<double>(bodies - 3);
      BodyPose& pose = frame.bodies[3 + static_cast<std::size_t>(unit(random) * movable)];
      pose.placement =
          Transform2(6.28 * unit(random), Vec2(8.0 * unit(random) - 4.0, 3.0 * unit(random) - 1.5));
    } else {
      for (std::size_t b = 3; b < bodies; ++b) {
        if (unit(random) < 0.4) continue;  // at rest this frame
        const Transform2& p = frame.bodies[b].placement;
        const double angle = std::atan2(p.sin_angle(), p.cos_angle()) + 0.05 * (unit(random) - 0.5);
        Vec2 at = p.translation() + Vec2(0.01 * (unit(random) - 0.5), -0.015 * unit(random));
        if (at.y() < -0.65) at.y() = 0.6;  // fell through: start again at the top
        frame.bodies[b].placement = Transform2(angle, at);
      }
    }
    clip.push_back(frame);
  }
  return clip;
}

// Redrawing only where bodies moved gives, frame after frame, exactly the pixels of drawing
// every frame whole: with shader and no anti-aliasing, with the rugosity overlay (wider
// outlines), and through moves off the frame and back.
TEST(SceneRenderer, IncrementalRedrawIsBitIdenticalToFullRedraw) {
  const std::vector<BodyLook> bodies = busy_bodies();
  for (const auto& [aa, rugosity, seed] :
       {std::tuple{AntiAliasing::kShader, false, 1u}, std::tuple{AntiAliasing::kNone, false, 2u},
        std::tuple{AntiAliasing::kShader, true, 3u}}) {
    std::unique_ptr<GlContext> a = GlContext::create(GlBackend::kOsmesa, 640, 360);
    std::unique_ptr<GlContext> b = GlContext::create(GlBackend::kOsmesa, 640, 360);
    SceneRenderer incremental(*a, bodies, busy_settings(aa, true, rugosity));
    SceneRenderer full(*b, bodies, busy_settings(aa, false, rugosity));
    const std::vector<FrameSnapshot> clip = busy_clip(bodies.size(), seed);
    ASSERT_EQ(testing::first_different_frame(incremental, full, clip), std::nullopt)
        << "anti-aliasing " << anti_aliasing_name(aa) << ", rugosity " << rugosity;
    EXPECT_GT(incremental.frames_partial(), clip.size() / 2);
    EXPECT_EQ(full.frames_partial(), 0u);
    // About five of the nine small bodies move in a frame, each covering 2% of it or less with
    // its old and new places: partial frames redraw about a fifth of the frame (measured 0.18 to
    // 0.26). Rectangles grown much beyond the bodies would fail here long before the 60% past
    // which a frame is drawn whole.
    const double share = static_cast<double>(incremental.pixels_redrawn()) /
                         (static_cast<double>(incremental.frames_partial()) * 640 * 360);
    EXPECT_LT(share, 0.35);
    RecordProperty("redrawn_share_" + std::to_string(seed), std::to_string(share));
  }
}

// One small body moving redraws only around it; MSAA and the contact and velocity overlays
// (which change all over the frame) always draw the whole frame.
TEST(SceneRenderer, IncrementalRedrawCoversOnlyWhatMoved) {
  const std::vector<BodyLook> bodies = busy_bodies();
  std::vector<FrameSnapshot> clip = busy_clip(bodies.size(), 9);
  FrameSnapshot first = clip.front();
  FrameSnapshot second = first;
  second.frame = 1;
  const Transform2& p = second.bodies[9].placement;  // the small disk
  second.bodies[9].placement =
      Transform2(std::atan2(p.sin_angle(), p.cos_angle()), p.translation() + Vec2(0.0, -0.01));
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, 640, 360);
  SceneRenderer renderer(*context, bodies, busy_settings(AntiAliasing::kShader, true, false));
  renderer.draw(first);
  renderer.draw(second);
  EXPECT_EQ(renderer.frames_partial(), 1u);
  // The disk is 0.2 m = 40 px across: the rectangle of its box turned (up to √2 wider), before
  // and after, with the outline and margins: about 1% of the frame, not all of it.
  EXPECT_LT(renderer.pixels_redrawn(), 70 * 70);
  EXPECT_GT(renderer.pixels_redrawn(), 40 * 40);

  for (const auto& [aa, overlays] :
       {std::pair{AntiAliasing::kMsaa, Overlays{}},
        std::pair{AntiAliasing::kShader, Overlays{false, true, false}},
        std::pair{AntiAliasing::kShader, Overlays{false, false, true}}}) {
    RenderSettings s = busy_settings(aa, true, false);
    s.overlays = overlays;
    SceneRenderer whole(*context, bodies, s);
    whole.draw(first);
    whole.draw(second);
    EXPECT_EQ(whole.frames_partial(), 0u);
  }
}

// Each picture drawn gets a number of its own, in every renderer; a frame at rest keeps it, and
// reading it into an image that holds it already leaves the image as it is.
TEST(SceneRenderer, PicturesAreNumberedAndNotReadTwice) {
  std::unique_ptr<GlContext> context = GlContext::create(GlBackend::kOsmesa, kWidth, kHeight);
  SceneRenderer renderer(*context, known_bodies(0.0), settings(AntiAliasing::kShader));
  EXPECT_EQ(renderer.picture(), 0u);
  renderer.draw(known_frame());
  const std::uint64_t first = renderer.picture();
  EXPECT_NE(first, 0u);
  Image image;
  renderer.read(image);
  EXPECT_EQ(image.picture, first);
  const Image drawn = image;
  renderer.draw(known_frame());  // at rest: the same picture
  EXPECT_EQ(renderer.picture(), first);
  std::fill(image.rgba.begin(), image.rgba.begin() + 4, std::uint8_t{1});  // unseen by read
  renderer.read(image);
  EXPECT_NE(image.rgba, drawn.rgba);  // not read again: the number says it is there
  image.picture = 0;                  // the pixels were changed, so the number goes
  renderer.read(image);
  EXPECT_EQ(image.rgba, drawn.rgba);
  FrameSnapshot moved = known_frame();
  moved.bodies[0].placement = Transform2(0.0, Vec2(-1.0, -0.2));
  renderer.draw(moved);
  EXPECT_GT(renderer.picture(), first);
  SceneRenderer other(*context, known_bodies(0.0), settings(AntiAliasing::kShader));
  other.draw(known_frame());
  EXPECT_NE(other.picture(), first);
  EXPECT_NE(other.picture(), renderer.picture());
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
