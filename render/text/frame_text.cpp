#include "render/text/frame_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace rugosim {
namespace {}  // namespace

void ImageTextCanvas::rect(int x0, int y0, int x1, int y1,
                           const std::array<std::uint8_t, 4>& colour) {
  for (int y = std::max(0, y0); y < std::min(image_.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(image_.width, x1); ++x)
      blend_over(image_.pixel(x, y), colour, colour[3]);
  }
  image_.picture = 0;
}

std::optional<Corner> parse_corner(const std::string& name) {
  if (name == "top-left") return Corner::kTopLeft;
  if (name == "top-right") return Corner::kTopRight;
  if (name == "bottom-left") return Corner::kBottomLeft;
  if (name == "bottom-right") return Corner::kBottomRight;
  return std::nullopt;
}

std::array<std::uint8_t, 3> rugosity_ramp(double x) {
  // The shader's numbers and arithmetic (float mix), so the bar shows the outlines' colours.
  const float t = static_cast<float>(std::clamp(x, 0.0, 1.0));
  const float a[3] = {0.267f, 0.005f, 0.329f};
  const float b[3] = {0.128f, 0.567f, 0.551f};
  const float c[3] = {0.993f, 0.906f, 0.144f};
  std::array<std::uint8_t, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    const float v =
        t < 0.5f ? a[i] + (b[i] - a[i]) * (t * 2.f) : b[i] + (c[i] - b[i]) * (t * 2.f - 1.f);
    out[i] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255.f));
  }
  return out;
}

std::string clock_text(const std::string& format, double time) {
  char text[256];
  // The format holds exactly one %f or %.Nf (checked when the scene is read).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
  std::snprintf(text, sizeof text, format.c_str(), time);
#pragma GCC diagnostic pop
  return text;
}

double scale_bar_length(double frame_width) {
  const double most = frame_width / 5.0;
  double decade = std::pow(10.0, std::floor(std::log10(most)));
  double best = decade;
  for (const double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade <= most * (1.0 + 1e-9)) best = step * decade;
  }
  return best;
}

std::string length_label(double metres) {
  struct Unit {
    double size;
    const char* name;
  };
  static constexpr Unit kUnits[] = {
      {1e3, "km"}, {1.0, "m"}, {1e-2, "cm"}, {1e-3, "mm"}, {1e-6, "µm"}};
  for (const Unit& u : kUnits) {
    if (metres >= u.size * (1.0 - 1e-9)) {
      char text[64];
      std::snprintf(text, sizeof text, "%.3g %s", metres / u.size, u.name);
      return text;
    }
  }
  char text[64];
  std::snprintf(text, sizeof text, "%g m", metres);
  return text;
}

TextLayout text_layout(int height) {
  const auto px = [&](double divisor) {
    return std::max(8, static_cast<int>(std::lround(height / divisor)));
  };
  TextLayout t;
  t.margin = std::max(2, static_cast<int>(std::lround(height / 40.0)));
  t.title_px = px(18.0);
  t.caption_px = px(30.0);
  t.clock_px = px(28.0);
  t.bar_thickness = std::max(2, static_cast<int>(std::lround(height / 180.0)));
  return t;
}

int strip_label_band(int frame_height) {
  return static_cast<int>(std::lround(1.6 * text_layout(frame_height).clock_px));
}

void label_strip(Image& strip, const StripGrid& grid, int frame_width, int frame_height,
                 const std::vector<std::string>& labels,
                 const std::array<std::uint8_t, 4>& colour) {
  if (labels.empty()) return;
  Font font(default_font_path());
  const int px = text_layout(frame_height).clock_px;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto [x, y] = grid_cell(grid, frame_width, frame_height, i, labels.size());
    const TextExtent e = font.measure(labels[i], px);
    const int baseline = y + frame_height + (grid.label_px + e.ascent - e.descent) / 2;
    font.draw(strip, labels[i], px, x + (frame_width - e.width) / 2, baseline, colour);
  }
}

void FrameTextPainter::paint_colour_bar(TextCanvas& canvas) {
  const int w = canvas.width();
  const int h = canvas.height();
  const TextLayout layout = text_layout(h);
  const int length = std::max(8, w / 5);
  const int thickness = std::max(4, h / 60);
  const bool left =
      text_.colour_bar_corner == Corner::kTopLeft || text_.colour_bar_corner == Corner::kBottomLeft;
  const bool top =
      text_.colour_bar_corner == Corner::kTopLeft || text_.colour_bar_corner == Corner::kTopRight;
  const int px = layout.clock_px;
  const TextExtent e = font_->measure("λ", px);
  // The name above the bar, the ends' values below it: from the corner, label, bar, values.
  const int block = e.ascent + e.descent + layout.bar_thickness + thickness + layout.bar_thickness +
                    e.ascent + e.descent;
  const int x0 = left ? layout.margin : w - layout.margin - length;
  const int y_top = top ? layout.margin : h - layout.margin - block;
  const int bar_top = y_top + e.ascent + e.descent + layout.bar_thickness;
  for (int x = 0; x < length; ++x) {
    const auto rgb = rugosity_ramp(static_cast<double>(x) / std::max(1, length - 1));
    const std::array<std::uint8_t, 4> colour{rgb[0], rgb[1], rgb[2], 255};
    canvas.rect(x0 + x, bar_top, x0 + x + 1, bar_top + thickness, colour);
  }
  const std::string name = "rugosity tolerance λ";
  const TextExtent n = font_->measure(name, px);
  canvas.text(name, px, x0 + (length - n.width) / 2, y_top + e.ascent, text_.colour);
  const int values = bar_top + thickness + layout.bar_thickness + e.ascent;
  canvas.text("0", px, x0, values, text_.colour);
  const std::string most = length_label(text_.largest_lambda);
  const TextExtent m = font_->measure(most, px);
  canvas.text(most, px, x0 + length - m.width, values, text_.colour);
}

FrameTextPainter::FrameTextPainter(FrameText text) : text_(std::move(text)) {
  if (text_.any()) font_ = std::make_unique<Font>(default_font_path());
}

std::array<int, 2> FrameTextPainter::corner_origin(const std::string& text, int px, Corner corner,
                                                   int width, int height) {
  const TextLayout layout = text_layout(height);
  const TextExtent e = font_->measure(text, px);
  const bool left = corner == Corner::kTopLeft || corner == Corner::kBottomLeft;
  const bool top = corner == Corner::kTopLeft || corner == Corner::kTopRight;
  const int x = left ? layout.margin : width - layout.margin - e.width;
  const int baseline = top ? layout.margin + e.ascent : height - layout.margin - e.descent;
  return {x, baseline};
}

std::array<int, 2> FrameTextPainter::clock_origin(const std::string& text, int width, int height) {
  return corner_origin(text, text_layout(height).clock_px, text_.clock_corner, width, height);
}

void FrameTextPainter::paint(Image& image, double time, double metres_per_pixel) {
  if (!font_) return;
  ImageTextCanvas canvas(image, *font_);
  paint(canvas, time, metres_per_pixel);
}

void FrameTextPainter::paint(TextCanvas& canvas, double time, double metres_per_pixel) {
  if (!font_) return;
  const int w = canvas.width();
  const int h = canvas.height();
  const TextLayout layout = text_layout(h);
  const auto centred = [&](const std::string& s, int px, bool top) {
    const TextExtent e = font_->measure(s, px);
    const int baseline = top ? layout.margin + e.ascent : h - layout.margin - e.descent;
    canvas.text(s, px, (w - e.width) / 2, baseline, text_.colour);
  };
  if (!text_.title.empty()) centred(text_.title, layout.title_px, true);
  if (!text_.caption.empty()) centred(text_.caption, layout.caption_px, false);
  if (text_.clock) {
    const std::string s = clock_text(text_.clock_format, time);
    const auto [x, baseline] = clock_origin(s, w, h);
    canvas.text(s, layout.clock_px, x, baseline, text_.colour);
  }
  if (text_.colour_bar) paint_colour_bar(canvas);
  if (text_.scale_bar && metres_per_pixel > 0.0) {
    const double metres = text_.scale_bar_length > 0.0 ? text_.scale_bar_length
                                                       : scale_bar_length(w * metres_per_pixel);
    const int length = std::max(1, static_cast<int>(std::lround(metres / metres_per_pixel)));
    const bool left =
        text_.scale_bar_corner == Corner::kTopLeft || text_.scale_bar_corner == Corner::kBottomLeft;
    const bool top =
        text_.scale_bar_corner == Corner::kTopLeft || text_.scale_bar_corner == Corner::kTopRight;
    const std::string label = length_label(metres);
    const TextExtent e = font_->measure(label, layout.clock_px);
    const int x0 = left ? layout.margin : w - layout.margin - length;
    // The label sits above the bar, centred on it; at the top the bar goes under the label.
    const int gap = layout.bar_thickness;
    int bar_top = 0;
    int baseline = 0;
    if (top) {
      baseline = layout.margin + e.ascent;
      bar_top = baseline + e.descent + gap;
    } else {
      bar_top = h - layout.margin - layout.bar_thickness;
      baseline = bar_top - gap - e.descent;
    }
    canvas.rect(x0, bar_top, x0 + length, bar_top + layout.bar_thickness, text_.colour);
    canvas.text(label, layout.clock_px, x0 + (length - e.width) / 2, baseline, text_.colour);
  }
}

}  // namespace rugosim
