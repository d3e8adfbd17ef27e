#include "render/draw/palette.h"

#include <array>

namespace rugosim {
namespace {

constexpr std::array<const char*, 8> kMoving = {"#c9795f", "#6f97b3", "#d8ae62", "#86a877",
                                                "#a987b3", "#e09a55", "#5f9c98", "#c26b7d"};
constexpr const char* kFixed = "#a39a8c";
constexpr const char* kDarkFixed = "#5d5a55";
// Greys far enough apart to tell neighbours apart on paper, none as dark as the outlines.
constexpr std::array<const char*, 4> kPrintMoving = {"#e6e6e6", "#b8b8b8", "#d0d0d0", "#a0a0a0"};
constexpr const char* kPrintFixed = "#8a8a8a";

Rgba hex(const char* text) {
  return *parse_hex_color(text);
}

}  // namespace

std::optional<Theme> parse_theme(std::string_view name) {
  if (name == "paper") return Theme::kPaper;
  if (name == "dark") return Theme::kDark;
  if (name == "print") return Theme::kPrint;
  return std::nullopt;
}

Rgba theme_background(Theme theme) {
  switch (theme) {
    case Theme::kDark:
      return hex("#1c1d21");
    case Theme::kPrint:
      return hex("#ffffff");
    case Theme::kPaper:
      break;
  }
  return hex("#f4f1ea");
}

Rgba theme_text_colour(Theme theme) {
  switch (theme) {
    case Theme::kDark:
      return hex("#e8e6e1");
    case Theme::kPrint:
      return hex("#000000");
    case Theme::kPaper:
      break;
  }
  return hex("#222222");
}

Rgba default_body_colour(std::size_t moving_index, bool fixed, Theme theme) {
  if (theme == Theme::kPrint) {
    return hex(fixed ? kPrintFixed : kPrintMoving[moving_index % kPrintMoving.size()]);
  }
  if (fixed) return hex(theme == Theme::kDark ? kDarkFixed : kFixed);
  return hex(kMoving[moving_index % kMoving.size()]);
}

Rgba theme_outline_colour(const Rgba& fill, Theme theme) {
  Rgba out;
  for (std::size_t c = 0; c < 3; ++c) {
    const float f = fill.channels[c];
    out.channels[c] = theme == Theme::kPrint  ? 0.f
                      : theme == Theme::kDark ? f + 0.55f * (1.f - f)
                                              : 0.45f * f;
  }
  out.channels[3] = 1.f;
  return out;
}

Rgba outline_colour(const Rgba& fill) {
  return theme_outline_colour(fill, Theme::kPaper);
}

}  // namespace rugosim
