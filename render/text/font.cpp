#include "render/text/font.h"

#include <algorithm>
#include <cstdlib>
#include <ft2build.h>
#include <stdexcept>
#include FT_FREETYPE_H

namespace rugosim {
namespace {

std::string freetype_error(FT_Error error) {
  const char* text = FT_Error_String(error);
  return text != nullptr ? text : "FreeType error " + std::to_string(error);
}

}  // namespace

void blend_over(std::uint8_t* pixel, const std::array<std::uint8_t, 4>& colour, unsigned alpha) {
  // Straight alpha "over": out_a = a + d(1 − a), out_c = (c a + d_c d (1 − a)) / out_a.
  const unsigned below = (pixel[3] * (255u - alpha) + 127u) / 255u;
  const unsigned out_a = alpha + below;
  for (std::size_t c = 0; c < 3; ++c) {
    const unsigned mixed = colour[c] * alpha + pixel[c] * below;
    pixel[c] = static_cast<std::uint8_t>(out_a == 0 ? 0u : (mixed + out_a / 2) / out_a);
  }
  pixel[3] = static_cast<std::uint8_t>(out_a);
}

std::string default_font_path() {
  const char* chosen = std::getenv("RUGOSIM_FONT");
  return chosen != nullptr && *chosen != '\0' ? std::string(chosen)
                                              : std::string(RUGOSIM_DEFAULT_FONT);
}

std::vector<char32_t> decode_utf8(std::string_view text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    int more = 0;
    char32_t code = 0;
    if (lead < 0x80) {
      code = lead;
    } else if ((lead & 0xE0) == 0xC0) {
      more = 1;
      code = lead & 0x1Fu;
    } else if ((lead & 0xF0) == 0xE0) {
      more = 2;
      code = lead & 0x0Fu;
    } else if ((lead & 0xF8) == 0xF0) {
      more = 3;
      code = lead & 0x07u;
    } else {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    bool valid = i + static_cast<std::size_t>(more) < text.size();
    for (int k = 1; valid && k <= more; ++k) {
      const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      valid = (next & 0xC0) == 0x80;
      code = (code << 6) | (next & 0x3Fu);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not characters.
    static constexpr char32_t kLeast[] = {0, 0x80, 0x800, 0x10000};
    valid = valid && code >= kLeast[more] && code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
    if (!valid) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    out.push_back(code);
    i += static_cast<std::size_t>(more) + 1;
  }
  return out;
}

struct Font::Face {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  int pixel_height = 0;  // the size set on the face now
  ~Face() {
    if (face != nullptr) FT_Done_Face(face);
    if (library != nullptr) FT_Done_FreeType(library);
  }
  void size(int px) {
    if (px == pixel_height) return;
    const FT_Error error = FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(px));
    if (error != 0) throw std::runtime_error("setting the text size: " + freetype_error(error));
    pixel_height = px;
  }
};

Font::Font(const std::string& path) : path_(path), face_(std::make_unique<Face>()) {
  FT_Error error = FT_Init_FreeType(&face_->library);
  if (error != 0) throw std::runtime_error("starting FreeType: " + freetype_error(error));
  error = FT_New_Face(face_->library, path.c_str(), 0, &face_->face);
  if (error != 0) {
    throw std::runtime_error(path + ": cannot open the font (" + freetype_error(error) +
                             "; install fonts-dejavu-core or set RUGOSIM_FONT)");
  }
}

Font::~Font() = default;

const Font::Glyph& Font::glyph(char32_t code, int pixel_height) {
  const auto key = std::make_pair(pixel_height, code);
  const auto found = glyphs_.find(key);
  if (found != glyphs_.end()) return found->second;
  face_->size(pixel_height);
  FT_Face face = face_->face;
  Glyph g;
  g.index = FT_Get_Char_Index(face, code);
  // Hinting off: the same shapes at every size, only sampled more finely.
  FT_Error error = FT_Load_Glyph(face, g.index, FT_LOAD_NO_HINTING);
  if (error == 0) error = FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL);
  if (error != 0) throw std::runtime_error(path_ + ": drawing a glyph: " + freetype_error(error));
  const FT_Bitmap& bitmap = face->glyph->bitmap;
  g.left = face->glyph->bitmap_left;
  g.top = face->glyph->bitmap_top;
  g.advance = static_cast<int>((face->glyph->advance.x + 32) >> 6);
  g.width = static_cast<int>(bitmap.width);
  g.rows = static_cast<int>(bitmap.rows);
  g.coverage.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.rows));
  for (int y = 0; y < g.rows; ++y) {
    const unsigned char* row = bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bitmap.pitch;
    std::copy(row, row + g.width, g.coverage.begin() + static_cast<std::ptrdiff_t>(y) * g.width);
  }
  return glyphs_.emplace(key, std::move(g)).first->second;
}

int Font::kerning(unsigned left, unsigned right, int pixel_height) {
  if (left == 0 || right == 0 || !FT_HAS_KERNING(face_->face)) return 0;
  face_->size(pixel_height);
  FT_Vector delta{};
  if (FT_Get_Kerning(face_->face, left, right, FT_KERNING_DEFAULT, &delta) != 0) return 0;
  return static_cast<int>((delta.x + 32) >> 6);
}

TextExtent Font::measure(std::string_view text, int pixel_height) {
  TextExtent extent;
  unsigned previous = 0;
  for (const char32_t code : decode_utf8(text)) {
    const Glyph& g = glyph(code, pixel_height);
    extent.width += kerning(previous, g.index, pixel_height) + g.advance;
    previous = g.index;
  }
  face_->size(pixel_height);
  const FT_Size_Metrics& metrics = face_->face->size->metrics;
  extent.ascent = static_cast<int>((metrics.ascender + 32) >> 6);
  extent.descent = static_cast<int>((-metrics.descender + 32) >> 6);
  return extent;
}

std::vector<PlacedGlyph> Font::place(std::string_view text, int pixel_height) {
  std::vector<PlacedGlyph> placed;
  int pen = 0;
  unsigned previous = 0;
  for (const char32_t code : decode_utf8(text)) {
    const Glyph& g = glyph(code, pixel_height);
    pen += kerning(previous, g.index, pixel_height);
    previous = g.index;
    placed.push_back({g.index, pen, code});
    pen += g.advance;
  }
  return placed;
}

void Font::draw(Image& image, std::string_view text, int pixel_height, int x, int baseline,
                const std::array<std::uint8_t, 4>& colour) {
  // The pens as place() lays them out, so that raster and vector text never part.
  for (const PlacedGlyph& placed : place(text, pixel_height)) {
    const Glyph& g = glyph(placed.code, pixel_height);
    const int pen = x + placed.x;
    for (int row = 0; row < g.rows; ++row) {
      const int py = baseline - g.top + row;
      if (py < 0 || py >= image.height) continue;
      for (int column = 0; column < g.width; ++column) {
        const int px = pen + g.left + column;
        if (px < 0 || px >= image.width) continue;
        const unsigned coverage =
            g.coverage[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.width) +
                       static_cast<std::size_t>(column)];
        const unsigned a = (coverage * colour[3] + 127u) / 255u;  // the text's alpha here
        if (a == 0) continue;
        blend_over(image.pixel(px, py), colour, a);
      }
    }
  }
  image.picture = 0;  // the pixels changed
}

}  // namespace rugosim
