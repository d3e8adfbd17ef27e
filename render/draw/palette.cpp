#include "render/draw/palette.h"

#include <array>

namespace rugosim {
namespace {

constexpr std::array<const char*, 8> kMoving = {"#c9795f", "#6f97b3", "#d8ae62", "#86a877",
                                                "#a987b3", "#e09a55", "#5f9c98", "#c26b7d"};
constexpr const char* kFixed = "#a39a8c";

}  // namespace

Rgba default_body_colour(std::size_t moving_index, bool fixed) {
  const char* hex = fixed ? kFixed : kMoving[moving_index % kMoving.size()];
  return *parse_hex_color(hex);
}

Rgba outline_colour(const Rgba& fill) {
  Rgba out;
  for (std::size_t c = 0; c < 3; ++c)
    out.channels[c] = 0.45f * fill.channels[c];
  out.channels[3] = 1.f;
  return out;
}

}  // namespace rugosim
