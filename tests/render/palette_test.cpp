// The themes' colours (palette.h): print stays grey, its outlines and text black; dark has a
// dark background with light text and outlines lighter than their fills; paper is today's look.
#include "render/draw/palette.h"

#include <gtest/gtest.h>

namespace rugosim {
namespace {

float luminance(const Rgba& c) {
  return 0.2126f * c.channels[0] + 0.7152f * c.channels[1] + 0.0722f * c.channels[2];
}

TEST(Palette, ThemesByName) {
  EXPECT_EQ(parse_theme("paper"), Theme::kPaper);
  EXPECT_EQ(parse_theme("dark"), Theme::kDark);
  EXPECT_EQ(parse_theme("print"), Theme::kPrint);
  EXPECT_FALSE(parse_theme("neon").has_value());
}

TEST(Palette, PrintIsGreyWithBlackOutlinesAndNeighboursApart) {
  for (std::size_t i = 0; i < 8; ++i) {
    const Rgba fill = default_body_colour(i, false, Theme::kPrint);
    EXPECT_EQ(fill.channels[0], fill.channels[1]);
    EXPECT_EQ(fill.channels[1], fill.channels[2]);
    const Rgba next = default_body_colour(i + 1, false, Theme::kPrint);
    EXPECT_GT(std::abs(luminance(fill) - luminance(next)), 0.05f) << i;
    const Rgba outline = theme_outline_colour(fill, Theme::kPrint);
    EXPECT_EQ(luminance(outline), 0.f);
  }
  EXPECT_EQ(luminance(theme_text_colour(Theme::kPrint)), 0.f);
  EXPECT_FLOAT_EQ(luminance(theme_background(Theme::kPrint)), 1.f);
}

TEST(Palette, DarkHasLightTextAndOutlinesLighterThanFills) {
  EXPECT_LT(luminance(theme_background(Theme::kDark)), 0.15f);
  EXPECT_GT(luminance(theme_text_colour(Theme::kDark)), 0.85f);
  for (std::size_t i = 0; i < 8; ++i) {
    const Rgba fill = default_body_colour(i, false, Theme::kDark);
    EXPECT_GT(luminance(theme_outline_colour(fill, Theme::kDark)), luminance(fill));
  }
}

TEST(Palette, PaperIsTheLookItAlwaysHad) {
  const Rgba paper = theme_background(Theme::kPaper);
  EXPECT_EQ(paper.channels, parse_hex_color("#f4f1ea")->channels);
  const Rgba fill = default_body_colour(0, false);
  EXPECT_EQ(fill.channels, parse_hex_color("#c9795f")->channels);
  EXPECT_EQ(outline_colour(fill).channels, theme_outline_colour(fill, Theme::kPaper).channels);
  EXPECT_LT(luminance(outline_colour(fill)), luminance(fill));
}

}  // namespace
}  // namespace rugosim
