// Text in frames (render/text): UTF-8 decoding, the clock's and the scale bar's words and
// lengths, and FreeType's text: drawn only inside its measured box, the same shapes at every
// size (only sampled more finely), composited with straight alpha.
#include "render/text/frame_text.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/text/font.h"

namespace rugosim {
namespace {

Image flat(int width, int height, std::array<std::uint8_t, 4> colour) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    image.rgba[i] = colour[i % 4];
  return image;
}

TEST(DecodeUtf8, CodePointsAndReplacementsForBadBytes) {
  EXPECT_EQ(decode_utf8("t = 1"), (std::vector<char32_t>{U't', U' ', U'=', U' ', U'1'}));
  EXPECT_EQ(decode_utf8("σλ€😀"), (std::vector<char32_t>{0x3C3, 0x3BB, 0x20AC, 0x1F600}));
  EXPECT_EQ(decode_utf8("a\xFF"
                        "b"),
            (std::vector<char32_t>{U'a', 0xFFFD, U'b'}));
  EXPECT_EQ(decode_utf8("\xC0\xAF"), (std::vector<char32_t>{0xFFFD, 0xFFFD}))  // overlong
      << "an overlong '/' is not a character";
  EXPECT_EQ(decode_utf8("\xE2\x82"), (std::vector<char32_t>{0xFFFD, 0xFFFD}));  // cut short
  EXPECT_EQ(decode_utf8("\xED\xA0\x80").front(), char32_t{0xFFFD});             // a surrogate
}

TEST(ClockText, FormatsTheTime) {
  EXPECT_EQ(clock_text("t = %.2f s", 1.5), "t = 1.50 s");
  EXPECT_EQ(clock_text("%.0f%% done", 42.4), "42% done");
  EXPECT_EQ(clock_text("%f", 0.25), "0.250000");
}

TEST(ScaleBar, LengthsOfOneTwoOrFiveTimesAPowerOfTenWithinAFifthOfTheFrame) {
  EXPECT_DOUBLE_EQ(scale_bar_length(4.62), 0.5);
  EXPECT_DOUBLE_EQ(scale_bar_length(10.0), 2.0);
  EXPECT_DOUBLE_EQ(scale_bar_length(0.05), 0.01);
  EXPECT_DOUBLE_EQ(scale_bar_length(30.0), 5.0);
  for (double width = 1e-4; width < 1e5; width *= 1.37) {
    const double bar = scale_bar_length(width);
    EXPECT_LE(bar, width / 5.0 * (1 + 1e-9)) << width;
    EXPECT_GT(bar, width / 5.0 / 2.5 * (1 - 1e-9)) << width;
  }
  EXPECT_EQ(length_label(0.5), "50 cm");
  EXPECT_EQ(length_label(2.0), "2 m");
  EXPECT_EQ(length_label(0.005), "5 mm");
  EXPECT_EQ(length_label(2000.0), "2 km");
}

TEST(Font, DrawsOnlyInsideItsMeasuredBoxAndNothingForNoText) {
  Font font(default_font_path());
  const std::array<std::uint8_t, 4> paper{244, 241, 234, 255};
  Image image = flat(200, 60, paper);
  const Image before = image;
  font.draw(image, "", 24, 10, 40, {34, 34, 34, 255});
  EXPECT_EQ(image.rgba, before.rgba);
  const TextExtent e = font.measure("Rugosity 1.25", 24);
  EXPECT_GT(e.width, 100);
  EXPECT_GT(e.ascent, 15);
  font.draw(image, "Rugosity 1.25", 24, 10, 40, {34, 34, 34, 255});
  int changed = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (std::equal(image.pixel(x, y), image.pixel(x, y) + 4, before.pixel(x, y))) continue;
      ++changed;
      EXPECT_GE(x, 10 - 2);
      EXPECT_LE(x, 10 + e.width + 2);
      EXPECT_GE(y, 40 - e.ascent);
      EXPECT_LE(y, 40 + e.descent);
      EXPECT_EQ(image.pixel(x, y)[3], 255) << "over an opaque frame text stays opaque";
    }
  }
  EXPECT_GT(changed, 200);
}

TEST(Font, TheSameShapesAtEverySize) {
  Font font(default_font_path());
  // Unhinted: widths scale with the size (within the rounding of each advance).
  const double small = font.measure("t = 3.75 s", 20).width;
  const double large = font.measure("t = 3.75 s", 80).width;
  EXPECT_NEAR(large / small, 4.0, 0.15);
  // Ink coverage scales with the area.
  const auto ink = [&](int px) {
    Image image = flat(8 * px, 2 * px, {255, 255, 255, 255});
    font.draw(image, "t = 3.75 s", px, px / 2, 3 * px / 2, {0, 0, 0, 255});
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
      sum += 255.0 - image.rgba[i];
    return sum / 255.0;
  };
  EXPECT_NEAR(ink(80) / ink(20), 16.0, 16.0 * 0.05);
}

TEST(Font, OverATransparentFrameTheTextKeepsItsColourAndCarriesAlpha) {
  Font font(default_font_path());
  Image image = flat(120, 40, {0, 0, 0, 0});
  font.draw(image, "Ag", 30, 5, 30, {200, 40, 30, 255});
  bool partial = false;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    if (image.rgba[i + 3] == 0) continue;
    EXPECT_EQ(image.rgba[i], 200);
    EXPECT_EQ(image.rgba[i + 1], 40);
    EXPECT_EQ(image.rgba[i + 2], 30);
    partial = partial || image.rgba[i + 3] < 255;
  }
  EXPECT_TRUE(partial) << "anti-aliased edges";
}

TEST(Font, AMissingFontIsAnErrorNamingIt) {
  try {
    Font font("/no/such/font.ttf");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/font.ttf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fonts-dejavu-core"), std::string::npos) << e.what();
  }
}

TEST(FrameTextPainter, NoTextDrawsNothingAndOpensNoFont) {
  FrameTextPainter painter(FrameText{});
  Image image = flat(64, 36, {1, 2, 3, 255});
  image.picture = 7;
  const Image before = image;
  painter.paint(image, 1.0, 0.01);
  EXPECT_EQ(image.rgba, before.rgba);
  EXPECT_EQ(image.picture, 7u) << "an untouched frame keeps its picture number";
}

TEST(FrameTextPainter, TheScaleBarIsAsLongAsItsLengthOnTheFrame) {
  FrameText text;
  text.scale_bar = true;
  text.scale_bar_length = 0.5;
  FrameTextPainter painter(text);
  Image image = flat(640, 360, {255, 255, 255, 255});
  const double metres_per_pixel = 0.004;  // 0.5 m = 125 px
  painter.paint(image, 0.0, metres_per_pixel);
  const TextLayout layout = text_layout(360);
  const int row = 360 - layout.margin - layout.bar_thickness / 2 - 1;
  int dark = 0;
  for (int x = 0; x < 640; ++x)
    dark += image.pixel(x, row)[0] == 34 ? 1 : 0;
  EXPECT_EQ(dark, 125);
  EXPECT_EQ(image.pixel(layout.margin, row)[0], 34);
  EXPECT_EQ(image.pixel(layout.margin + 125, row)[0], 255);
}

}  // namespace
}  // namespace rugosim
