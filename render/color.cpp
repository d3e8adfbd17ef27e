#include "render/color.h"

namespace rugosim {

namespace {
int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

std::optional<Rgba> parse_hex_color(std::string_view text) {
  if (text.size() == 4 && text[0] == '#') {  // "#rgb" is "#rrggbb"
    Rgba color;
    for (std::size_t c = 0; c < 3; ++c) {
      const int digit = hex_digit(text[1 + c]);
      if (digit < 0) return std::nullopt;
      color.channels[c] = static_cast<float>(digit * 17) / 255.f;
    }
    return color;
  }
  if (text.size() != 7 && text.size() != 9) return std::nullopt;
  if (text[0] != '#') return std::nullopt;
  Rgba color;
  const std::size_t channels = (text.size() - 1) / 2;
  for (std::size_t c = 0; c < channels; ++c) {
    const int hi = hex_digit(text[1 + 2 * c]);
    const int lo = hex_digit(text[2 + 2 * c]);
    if (hi < 0 || lo < 0) return std::nullopt;
    color.channels[c] = static_cast<float>(hi * 16 + lo) / 255.f;
  }
  return color;
}

}  // namespace rugosim
