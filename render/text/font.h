// Text drawn into frames (titles, captions, the clock, the scale bar's label): a TrueType face
// rasterised by FreeType with its anti-aliasing (8-bit coverage) and kerning, composited on the
// CPU onto the frame read back from GL. Drawing on the CPU makes text the same pixels whatever
// GL backend drew the frame, and costs nothing when no text is asked for.
//
// The face is DejaVu Sans from Debian's fonts-dejavu-core (the path is compiled in, or the
// RUGOSIM_FONT environment variable names another TrueType or OpenType file).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "render/image.h"

namespace rugosim {

// Composites `colour` (straight RGBA) at coverage `alpha` (0..255, already times the colour's
// alpha) over the straight-alpha RGBA `pixel`.
void blend_over(std::uint8_t* pixel, const std::array<std::uint8_t, 4>& colour, unsigned alpha);

// The font text is drawn with: RUGOSIM_FONT when set, else DejaVu Sans where Debian puts it.
std::string default_font_path();

// The Unicode code points of UTF-8 text; a byte that does not start a valid sequence (or a
// sequence cut short) becomes U+FFFD.
std::vector<char32_t> decode_utf8(std::string_view text);

// A glyph of laid-out text: the face's glyph index and its pen's x, px from the text's start.
struct PlacedGlyph {
  unsigned index = 0;
  int x = 0;
  char32_t code = 0;  // the code point it draws
};

struct TextExtent {
  int width = 0;    // px, from the pen's start to the end of the last advance
  int ascent = 0;   // px above the baseline (the face's, at this size)
  int descent = 0;  // px below the baseline, ≥ 0
};

class Font {
 public:
  // Throws std::runtime_error naming `path` and FreeType's reason when it cannot be opened.
  explicit Font(const std::string& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  // `text` (UTF-8) at `pixel_height` (the em, px).
  TextExtent measure(std::string_view text, int pixel_height);
  // The glyphs of `text` at `pixel_height` and where their pens start (advances and kerning as
  // draw() places them): for writers that draw the same text as vector glyphs.
  std::vector<PlacedGlyph> place(std::string_view text, int pixel_height);
  // Draws `text` with its pen starting at (x, baseline) (px, y down), in `colour` (straight
  // RGBA), over what the image holds (straight alpha "over"); what falls outside is clipped.
  void draw(Image& image, std::string_view text, int pixel_height, int x, int baseline,
            const std::array<std::uint8_t, 4>& colour);

  const std::string& path() const { return path_; }

 private:
  struct Glyph {
    int left = 0;     // px from the pen to the bitmap's left edge
    int top = 0;      // px from the baseline up to the bitmap's top row
    int advance = 0;  // px, rounded from 26.6
    int width = 0, rows = 0;
    std::vector<std::uint8_t> coverage;  // rows × width, 0..255
    unsigned index = 0;                  // the face's glyph index (for kerning)
  };
  struct Face;  // FreeType's objects, kept out of this header

  const Glyph& glyph(char32_t code, int pixel_height);
  int kerning(unsigned left, unsigned right, int pixel_height);

  std::string path_;
  std::unique_ptr<Face> face_;
  std::map<std::pair<int, char32_t>, Glyph> glyphs_;  // by (pixel height, code point)
};

}  // namespace rugosim
