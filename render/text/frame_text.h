// The text and marks a frame may carry for slides and papers (render.title, render.caption,
// render.clock, render.scale_bar; docs/scene-format.md), laid out from the frame's height so
// that every size of the same frame looks the same, and drawn on the CPU (font.h) after the
// frame is read back: the same pixels whatever GL backend drew it.
//
// Layout, with H the frame's height and m = H/40 the margin: the title centred at the top
// (H/18 px), the caption centred at the bottom (H/30 px), the clock (H/28 px) and the scale bar
// (a bar H/180 px thick, at least 2, its label H/28 px above it) each in its corner.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/sinks/film_strip.h"
#include "render/text/font.h"
#include "render/text/text_canvas.h"

namespace rugosim {

enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };
// "top-left", "top-right", "bottom-left", "bottom-right".
std::optional<Corner> parse_corner(const std::string& name);

struct FrameText {
  std::string title;    // "" for none
  std::string caption;  // "" for none
  bool clock = false;
  Corner clock_corner = Corner::kTopLeft;
  std::string clock_format = "t = %.2f s";  // one %f or %.Nf (the scene loader checks it)
  bool scale_bar = false;
  Corner scale_bar_corner = Corner::kBottomLeft;
  double scale_bar_length = 0.0;  // m; 0: chosen from the frame's width (scale_bar_length)
  // The rugosity overlay's colour bar, from λ = 0 to `largest_lambda` (m), labelled.
  bool colour_bar = false;
  Corner colour_bar_corner = Corner::kBottomRight;
  double largest_lambda = 0.0;
  std::array<std::uint8_t, 4> colour{34, 34, 34, 255};  // straight RGBA

  bool any() const {
    return !title.empty() || !caption.empty() || clock || scale_bar || colour_bar;
  }
};

// The rugosity overlay's colour at x in [0, 1] (shaders/outline.vert's ramp: dark blue, smooth,
// through green to yellow, rough), RGB bytes.
std::array<std::uint8_t, 3> rugosity_ramp(double x);

// The clock's text at `time` (s).
std::string clock_text(const std::string& format, double time);
// The longest of 1, 2 or 5 × 10^k m that is at most a fifth of `frame_width` (m).
double scale_bar_length(double frame_width);
// "50 cm", "2 m", "5 mm", "1 km": the length in the unit that keeps the number from 1 to 999.
std::string length_label(double metres);

struct TextLayout {
  int margin = 0;
  int title_px = 0, caption_px = 0, clock_px = 0, bar_thickness = 0;
};
TextLayout text_layout(int height);

// The band under each frame of a strip that holds its label (px): 1.6 × the clock's text size
// for frames `frame_height` px high.
int strip_label_band(int frame_height);
// Writes labels[i] centred in the band under frame i of a strip laid out by `grid`
// (film_strip.h), in `colour` (straight RGBA). Throws std::runtime_error when the font cannot
// be opened.
void label_strip(Image& strip, const StripGrid& grid, int frame_width, int frame_height,
                 const std::vector<std::string>& labels, const std::array<std::uint8_t, 4>& colour);

class FrameTextPainter {
 public:
  // Opens the font (font.h: default_font_path()) only when there is text to draw. Throws
  // std::runtime_error naming the font when it cannot be opened.
  explicit FrameTextPainter(FrameText text);
  // Draws the frame's text over `image` (the frame at `time` s, `metres_per_pixel` its scale).
  void paint(Image& image, double time, double metres_per_pixel);
  // The same layout handed to any canvas (a vector page: vector_still.h).
  void paint(TextCanvas& canvas, double time, double metres_per_pixel);
  bool any() const { return font_ != nullptr; }
  // Where the clock's text starts (its pen) and its baseline, px, in a frame of this size.
  std::array<int, 2> clock_origin(const std::string& text, int width, int height);

 private:
  // The pen's x and the baseline for `text` at `px` in `corner`.
  std::array<int, 2> corner_origin(const std::string& text, int px, Corner corner, int width,
                                   int height);
  void paint_colour_bar(TextCanvas& canvas);

  FrameText text_;
  std::unique_ptr<Font> font_;  // null when there is no text
};

}  // namespace rugosim
