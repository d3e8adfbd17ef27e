// Colours as the scene file writes them ("#rgb", "#rrggbb", "#rrggbbaa") and as GL wants them.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace rugosim {

struct Rgba {
  std::array<float, 4> channels{0.f, 0.f, 0.f, 1.f};  // red, green, blue, alpha in [0, 1]
};

// "#rgb", "#rrggbb" or "#rrggbbaa"; nullopt for anything else.
std::optional<Rgba> parse_hex_color(std::string_view text);

}  // namespace rugosim
