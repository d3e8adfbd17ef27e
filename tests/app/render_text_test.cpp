// Text in rendered frames through the program (render.title, caption, clock, scale_bar): the
// clock's words are found pixel for pixel where the clock goes, at each frame's own time; the
// same pixels from both GL backends; and a scene without text keeps exactly its old frames.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/sinks/png_io.h"
#include "render/text/frame_text.h"
#include "support/render_command_fixture.h"

namespace {

namespace fs = std::filesystem;
using rugosim::FrameText;
using rugosim::FrameTextPainter;
using rugosim::Image;
using rugosim::read_png_file;
using rugosim::testing::differing_pixels;
using rugosim::testing::Outcome;
using rugosim::testing::RenderCommand;

// The top left of a frame, the clock's corner, up to the clock's text and its margin beyond
// (over the background of figure12a seen from afar, away from the container).
bool same_corner(const Image& a, const Image& b) {
  const int height = a.height / 10;
  const int width = a.width / 5;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!std::equal(a.pixel(x, y), a.pixel(x, y) + 4, b.pixel(x, y))) {
        return false;
      }
    }
  }
  return true;
}

// The corner as the painter alone draws `words` onto the scene's background.
Image expected_corner(const std::string& words, int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = 0xf4;
    image.rgba[i + 1] = 0xf1;
    image.rgba[i + 2] = 0xea;
    image.rgba[i + 3] = 255;
  }
  FrameText text;
  text.clock = true;
  text.clock_format = "%%";  // not used: the words are drawn as they are
  FrameTextPainter painter(text);
  const auto origin = painter.clock_origin(words, width, height);
  rugosim::Font font(rugosim::default_font_path());
  font.draw(image, words, rugosim::text_layout(height).clock_px, origin[0], origin[1], text.colour);
  return image;
}

TEST_F(RenderCommand, TheClockShowsEachFramesTimePixelForPixel) {
  // The fixed camera from farther away, so that the container's walls stay clear of the clock.
  std::string text = rugosim::testing::read_text(fixed_camera_scene(R"([], "clock": true)"));
  const std::string near = R"("height": 2.6)";
  ASSERT_NE(text.find(near), std::string::npos);
  text.replace(text.find(near), near.size(), R"("height": 4.5)");
  const fs::path scene = dir_ / "far.json";
  rugosim::testing::write_text(scene, text);
  for (const std::size_t k : {0u, 45u, 149u}) {
    const Image frame_image = frame(scene.string(), k, {"--size", "640x360"});
    ASSERT_EQ(frame_image.width, 640);
    const std::string words = rugosim::clock_text("t = %.2f s", static_cast<double>(k) / 30.0);
    EXPECT_TRUE(same_corner(frame_image, expected_corner(words, 640, 360)))
        << "frame " << k << " lacks \"" << words << "\"";
    // Another time's words are not there: the comparison can fail.
    const std::string other = rugosim::clock_text("t = %.2f s", static_cast<double>(k + 1) / 30.0);
    EXPECT_FALSE(same_corner(frame_image, expected_corner(other, 640, 360))) << other;
  }
}

TEST_F(RenderCommand, TextIsTheSamePixelsFromBothBackends) {
  const fs::path scene = fixed_camera_scene(
      R"x([], "title": "Eight rough rocks (σ = 3 mm)", "caption": "figure 12a", "clock": true, )x"
      R"x("scale_bar": {"corner": "bottom-right"})x");
  const Image osmesa = frame(scene.string(), 40, {"--backend", "osmesa"});
  const Image egl = frame(scene.string(), 40, {"--backend", "egl"});
  ASSERT_FALSE(osmesa.rgba.empty());
  EXPECT_EQ(differing_pixels(osmesa, egl), 0u);
  // And the text is there: the frame differs from the same one without text.
  const Image plain = frame(fixed_camera_scene().string(), 40, {});
  EXPECT_GT(differing_pixels(osmesa, plain), 500u);
}

}  // namespace
