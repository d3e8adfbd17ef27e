// Where frame text is drawn: the frame's pixels (ImageTextCanvas) or a vector page
// (render/sinks/vector_still.cpp). FrameTextPainter lays text out once, in pixels, and hands
// every string and rectangle to a canvas, so raster and vector outputs share one layout.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "render/image.h"
#include "render/text/font.h"

namespace rugosim {

class TextCanvas {
 public:
  virtual ~TextCanvas() = default;
  virtual int width() const = 0;   // px
  virtual int height() const = 0;  // px
  // `text` at `pixel_height` with its pen starting at (x, baseline), px, y down.
  virtual void text(std::string_view text, int pixel_height, int x, int baseline,
                    const std::array<std::uint8_t, 4>& colour) = 0;
  // The rectangle [x0, x1) × [y0, y1), px, y down.
  virtual void rect(int x0, int y0, int x1, int y1, const std::array<std::uint8_t, 4>& colour) = 0;
};

// Draws into an image with `font` (straight alpha "over").
class ImageTextCanvas final : public TextCanvas {
 public:
  ImageTextCanvas(Image& image, Font& font) : image_(image), font_(font) {}
  int width() const override { return image_.width; }
  int height() const override { return image_.height; }
  void text(std::string_view text, int pixel_height, int x, int baseline,
            const std::array<std::uint8_t, 4>& colour) override {
    font_.draw(image_, text, pixel_height, x, baseline, colour);
  }
  void rect(int x0, int y0, int x1, int y1, const std::array<std::uint8_t, 4>& colour) override;

 private:
  Image& image_;
  Font& font_;
};

}  // namespace rugosim
