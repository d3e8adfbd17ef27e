// How frames look through the program: render.theme (print stays grey, dark has its background),
// render.outline (colour and width), and --camera, which frames exactly as the scene's camera
// keys would.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/text/frame_text.h"
#include "support/file_text.h"
#include "support/render_command_fixture.h"

namespace {

namespace fs = std::filesystem;
using rugosim::Image;
using rugosim::testing::differing_pixels;
using rugosim::testing::figure12a;
using rugosim::testing::Outcome;
using rugosim::testing::RenderCommand;

TEST_F(RenderCommand, PrintThemeFramesAreGreyAndDarkOnesHaveTheirBackground) {
  const Image print =
      frame(fixed_camera_scene(R"([], "theme": "print", "clock": true)").string(), 40, {});
  ASSERT_FALSE(print.rgba.empty());
  std::size_t coloured = 0;
  for (std::size_t i = 0; i < print.rgba.size(); i += 4) {
    coloured += print.rgba[i] != print.rgba[i + 1] || print.rgba[i + 1] != print.rgba[i + 2];
  }
  EXPECT_EQ(coloured, 0u) << "every pixel of a print frame is grey";
  EXPECT_EQ(print.rgba[4 * 160 + 0], 255) << "a white background";

  const Image dark = frame(fixed_camera_scene(R"([], "theme": "dark")").string(), 40, {});
  ASSERT_FALSE(dark.rgba.empty());
  // The top middle of the frame is background: #1c1d21.
  const std::uint8_t* p = dark.pixel(160, 2);
  EXPECT_EQ(p[0], 0x1c);
  EXPECT_EQ(p[1], 0x1d);
  EXPECT_EQ(p[2], 0x21);
  // An explicit background wins over the theme's.
  const Image dark_on_white =
      frame(fixed_camera_scene(R"([], "theme": "dark", "background": "#ffffff")").string(), 40, {});
  EXPECT_EQ(dark_on_white.pixel(160, 2)[0], 255);
}

TEST_F(RenderCommand, OutlineColourAndWidthAreTheScenes) {
  const auto red_pixels = [&](const std::string& outline) {
    const Image image = frame(fixed_camera_scene("[], " + outline).string(), 40, {});
    std::size_t red = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
      red += image.rgba[i] == 255 && image.rgba[i + 1] == 0 && image.rgba[i + 2] == 0;
    return red;
  };
  const std::size_t thin = red_pixels(R"("outline": {"color": "#ff0000", "width": 1.5})");
  const std::size_t wide = red_pixels(R"("outline": {"color": "#ff0000", "width": 6})");
  EXPECT_GT(thin, 100u);
  EXPECT_GT(wide, 3 * thin) << "four times the width, several times the full-coverage pixels";
  EXPECT_EQ(red_pixels(R"("outline": {"width": 6})"), 0u) << "no red without the colour";
}

// render.colour_bar: the overlay's ramp from λ = 0 (left) to the largest λ (right), in the
// bottom-right corner, only while the rugosity overlay is drawn.
TEST_F(RenderCommand, ColourBarShowsTheRugosityRampOnlyWithItsOverlay) {
  const Image with_bar =
      frame(fixed_camera_scene(R"(["rugosity"], "colour_bar": true)").string(), 40, {});
  const Image without_bar = frame(fixed_camera_scene(R"(["rugosity"])").string(), 40, {});
  ASSERT_FALSE(with_bar.rgba.empty());
  const auto count = [&](const Image& image, std::array<std::uint8_t, 3> rgb) {
    std::size_t n = 0;
    for (int y = image.height * 3 / 4; y < image.height; ++y) {
      for (int x = image.width * 3 / 5; x < image.width; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        n += p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
      }
    }
    return n;
  };
  const auto smooth = rugosim::rugosity_ramp(0.0);
  const auto rough = rugosim::rugosity_ramp(1.0);
  EXPECT_GE(count(with_bar, smooth), 4u) << "the bar's left end";
  EXPECT_GE(count(with_bar, rough), 4u) << "the bar's right end";
  EXPECT_GT(differing_pixels(with_bar, without_bar), 300u);
  // Without the overlay the key draws nothing.
  const Image off = frame(fixed_camera_scene(R"([], "colour_bar": true)").string(), 40, {});
  EXPECT_EQ(differing_pixels(off, frame(fixed_camera_scene().string(), 40, {})), 0u);
}

TEST_F(RenderCommand, CameraOptionFramesAsTheScenesCameraKeys) {
  // fixed_camera_scene() sets {"center": [0, 1.1], "height": 2.6}; figure12a has "auto".
  const Image from_scene = frame(fixed_camera_scene().string(), 60, {});
  const Image from_option = frame(figure12a(), 60, {"--camera", "0,1.1,2.6"});
  ASSERT_FALSE(from_option.rgba.empty());
  EXPECT_EQ(differing_pixels(from_scene, from_option), 0u);
  const Image automatic = frame(fixed_camera_scene().string(), 60, {"--camera", "auto"});
  EXPECT_EQ(differing_pixels(automatic, frame(figure12a(), 60, {})), 0u);
  for (const std::string bad : {"1,2", "0,0,0", "a,b,c", "0,0,1,2"}) {
    const Outcome r = run(
        {figure12a(), "-o", (dir_ / "out" / "x.png").string(), "--frame", "1", "--camera", bad});
    EXPECT_EQ(r.code, 2) << bad << "\n" << r.err;
    EXPECT_NE(r.err.find("--camera"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "x.png"));
  }
}

// The pixel at the frame's centre, RGBA.
std::array<std::uint8_t, 4> centre_pixel(const Image& image) {
  const auto width = static_cast<std::size_t>(image.width);
  const std::size_t i = 4 * (static_cast<std::size_t>(image.height / 2) * width + width / 2);
  return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}

// --camera follow:BODY[,HEIGHT] and render.camera {"follow", "height"}: the same frames; the
// followed rock's centre of mass stays at the frame's centre (its fill there in every frame)
// while the picture around it changes; an unknown body exits 2 with a suggestion.
TEST_F(RenderCommand, FollowingCameraKeepsTheBodyAtTheCentre) {
  std::string text = rugosim::testing::read_text(figure12a());
  const std::string automatic = R"("camera": "auto")";
  ASSERT_NE(text.find(automatic), std::string::npos);
  text.replace(text.find(automatic), automatic.size(),
               R"("camera": {"follow": "rock_3", "height": 1.2})");
  const std::string keyed = (dir_ / "follow.json").string();
  rugosim::testing::write_text(keyed, text);
  std::vector<Image> frames;
  for (const std::size_t k : {0u, 40u, 120u}) {
    frames.push_back(frame(figure12a(), k, {"--camera", "follow:rock_3,1.2"}));
    ASSERT_FALSE(frames.back().rgba.empty());
    EXPECT_EQ(differing_pixels(frames.back(), frame(keyed, k, {})), 0u) << k;
  }
  EXPECT_EQ(centre_pixel(frames[0]), centre_pixel(frames[1]));
  EXPECT_EQ(centre_pixel(frames[0]), centre_pixel(frames[2]));
  EXPECT_GT(differing_pixels(frames[0], frames[2]), 1000u) << "the rest of the scene moves";
  // Without a height: four times the rock's size, so it covers a small part of the frame.
  const Image wide = frame(figure12a(), 40, {"--camera", "follow:rock_3"});
  std::size_t same = 0;
  for (std::size_t i = 0; i < wide.rgba.size(); i += 4) {
    same += std::equal(wide.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                       wide.rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                       centre_pixel(wide).begin())
                ? 1u
                : 0u;
  }
  EXPECT_EQ(centre_pixel(wide), centre_pixel(frames[1]));
  const auto pixels = static_cast<double>(wide.rgba.size() / 4);
  EXPECT_LT(static_cast<double>(same) / pixels, 0.15);
  EXPECT_GT(static_cast<double>(same) / pixels, 0.01);
  const Outcome r = run({figure12a(), "-o", (dir_ / "out" / "x.png").string(), "--frame", "1",
                         "--camera", "follow:rock3"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("no body named \"rock3\" (did you mean \"rock_3\"?)"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "x.png"));
}

}  // namespace
