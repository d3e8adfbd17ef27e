// Colours a body is drawn with when the scene gives none, by theme (render.theme):
//   paper  a warm paper background, a muted, distinguishable palette for moving bodies, a stone
//          grey for fixed ones, outlines the fill darkened, dark grey text (the default);
//   dark   a near-black background, the same fills, outlines the fill lightened, light text;
//   print  white, fills in light greys that stay apart in black and white, black outlines and
//          text: for papers printed without colour.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "render/color.h"

namespace rugosim {

enum class Theme { kPaper, kDark, kPrint };
std::optional<Theme> parse_theme(std::string_view name);  // "paper", "dark", "print"

Rgba theme_background(Theme theme);
Rgba theme_text_colour(Theme theme);
Rgba default_body_colour(std::size_t moving_index, bool fixed, Theme theme = Theme::kPaper);
// The outline of a body filled with `fill` (opaque): darkened on paper, lightened on dark,
// black in print.
Rgba theme_outline_colour(const Rgba& fill, Theme theme);
// The fill darkened (same hue), opaque: the paper theme's outline.
Rgba outline_colour(const Rgba& fill);

}  // namespace rugosim
