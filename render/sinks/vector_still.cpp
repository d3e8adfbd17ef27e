#include "render/sinks/vector_still.h"

#include <algorithm>
#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <cmath>
#include <ft2build.h>
#include <memory>
#include <stdexcept>
#include FT_FREETYPE_H

#include "engine/geometry/tolerance_profile.h"
#include "render/draw/overlay_geometry.h"
#include "render/draw/palette.h"
#include "render/draw/rugosity_detail.h"
#include "render/text/font.h"
#include "render/text/text_canvas.h"

namespace rugosim {
namespace {

struct CairoDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  void operator()(cairo_t* c) const { cairo_destroy(c); }
  void operator()(cairo_font_face_t* f) const { cairo_font_face_destroy(f); }
};
using Surface = std::unique_ptr<cairo_surface_t, CairoDeleter>;
using Context = std::unique_ptr<cairo_t, CairoDeleter>;
using FontFace = std::unique_ptr<cairo_font_face_t, CairoDeleter>;

void check(cairo_status_t status) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cannot make the vector still (cairo: ") +
                             cairo_status_to_string(status) + ")");
  }
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(closure);
  bytes->insert(bytes->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}

void set_colour(cairo_t* cr, const Rgba& c) {
  cairo_set_source_rgba(cr, c.channels[0], c.channels[1], c.channels[2], c.channels[3]);
}

void set_colour(cairo_t* cr, const std::array<std::uint8_t, 4>& c) {
  cairo_set_source_rgba(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
}

// FreeType's library for the faces cairo draws text with: cairo may keep a face after the page
// is written (its font cache), so the library lives as long as the process.
FT_Library freetype_library() {
  static FT_Library library = [] {
    FT_Library l = nullptr;
    if (FT_Init_FreeType(&l) != 0) throw std::runtime_error("starting FreeType failed");
    return l;
  }();
  return library;
}

// Text as glyph outlines, placed where Font::draw puts them in a raster frame.
class CairoTextCanvas final : public TextCanvas {
 public:
  CairoTextCanvas(cairo_t* cr, int width, int height)
      : cr_(cr), width_(width), height_(height), font_(default_font_path()) {
    FT_Face face = nullptr;
    if (FT_New_Face(freetype_library(), font_.path().c_str(), 0, &face) != 0) {
      throw std::runtime_error(font_.path() + ": cannot open the font for vector text");
    }
    face_.reset(cairo_ft_font_face_create_for_ft_face(face, FT_LOAD_NO_HINTING));
    // The face goes with cairo's font face, whenever cairo lets go of it.
    static const cairo_user_data_key_t key{};
    const cairo_status_t status = cairo_font_face_set_user_data(
        face_.get(), &key, face, [](void* f) { FT_Done_Face(static_cast<FT_Face>(f)); });
    if (status != CAIRO_STATUS_SUCCESS) {
      FT_Done_Face(face);
      throw std::runtime_error("cairo refused the font face");
    }
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  void text(std::string_view text, int pixel_height, int x, int baseline,
            const std::array<std::uint8_t, 4>& colour) override {
    std::vector<cairo_glyph_t> glyphs;
    for (const PlacedGlyph& g : font_.place(text, pixel_height))
      glyphs.push_back({g.index, static_cast<double>(x + g.x), static_cast<double>(baseline)});
    cairo_set_font_face(cr_, face_.get());
    cairo_set_font_size(cr_, pixel_height);  // the em in px, as FT_Set_Pixel_Sizes
    set_colour(cr_, colour);
    cairo_show_glyphs(cr_, glyphs.data(), static_cast<int>(glyphs.size()));
  }
  void rect(int x0, int y0, int x1, int y1, const std::array<std::uint8_t, 4>& colour) override {
    cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
    set_colour(cr_, colour);
    cairo_fill(cr_);
  }

 private:
  cairo_t* cr_;
  int width_, height_;
  Font font_;
  FontFace face_;
};

struct Page {
  cairo_t* cr;
  const Camera& camera;
  // A world point in page units (px, y down), as the GL frame's rows.
  std::array<double, 2> to_page(const Vec2& world) const {
    const Vec2 p = camera.to_pixels(world);
    return {0.5 * camera.width_px + p.x(), 0.5 * camera.height_px - p.y()};
  }
};

// Each body's outline in the world, in page units.
std::vector<std::vector<std::array<double, 2>>> placed_outlines(
    const std::vector<BodyLook>& looks, const RenderSettings& settings, const FrameSnapshot& frame,
    const Page& page, std::vector<DetailOutline>& outlines) {
  DetailSettings detail = settings.detail;
  detail.pixel_size = settings.camera.pixel_size();
  std::vector<std::vector<std::array<double, 2>>> placed;
  for (std::size_t b = 0; b < looks.size(); ++b) {
    outlines.push_back(make_detail_outline(looks[b].curve, looks[b].sigma, looks[b].seed, detail));
    std::vector<std::array<double, 2>> points;
    for (const Vec2& p : outlines.back().points)
      points.push_back(page.to_page(frame.bodies[b].placement.apply(p)));
    placed.push_back(std::move(points));
  }
  return placed;
}

bool off_page(const std::vector<std::array<double, 2>>& points, double reach, const Camera& c) {
  std::array<double, 2> lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (const auto& p : points) {
    for (std::size_t i = 0; i < 2; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  return hi[0] < -reach || hi[1] < -reach || lo[0] > c.width_px + reach ||
         lo[1] > c.height_px + reach;
}

void polygon_path(cairo_t* cr, const std::vector<std::array<double, 2>>& points) {
  cairo_new_path(cr);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0) {
      cairo_move_to(cr, points[i][0], points[i][1]);
    } else {
      cairo_line_to(cr, points[i][0], points[i][1]);
    }
  }
  cairo_close_path(cr);
}

// The outline coloured by λ: runs of edges whose start has the same colour (64 steps of the
// ramp) stroked together.
void stroke_by_lambda(cairo_t* cr, const std::vector<std::array<double, 2>>& points,
                      const DetailOutline& outline, const ToleranceProfile& profile,
                      std::size_t segments, double largest) {
  const std::size_t n = points.size();
  const auto step = [&](std::size_t i) {
    const double u = outline.param[i];
    const auto j = static_cast<std::size_t>(u) % segments;
    const double level = largest > 0.0 ? profile.at(j, u - std::floor(u)) / largest : 0.0;
    return static_cast<int>(std::lround(std::clamp(level, 0.0, 1.0) * 63.0));
  };
  std::size_t i = 0;
  while (i < n) {
    const int s = step(i);
    cairo_new_path(cr);
    cairo_move_to(cr, points[i][0], points[i][1]);
    std::size_t k = i;
    do {
      ++k;
      cairo_line_to(cr, points[k % n][0], points[k % n][1]);
    } while (k < n && step(k) == s);
    const auto rgb = rugosity_ramp(s / 63.0);
    cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    cairo_stroke(cr);
    i = k;
  }
}

}  // namespace

std::vector<std::uint8_t> make_vector_still(VectorFormat format, const std::vector<BodyLook>& looks,
                                            const RenderSettings& settings,
                                            const FrameSnapshot& frame, const FrameText& text) {
  const Camera& camera = settings.camera;
  if (frame.bodies.size() != looks.size()) {
    throw std::invalid_argument("vector still: the snapshot and the scene differ in bodies");
  }
  std::vector<std::uint8_t> bytes;
  Surface surface(format == VectorFormat::kSvg
                      ? cairo_svg_surface_create_for_stream(append_bytes, &bytes, camera.width_px,
                                                            camera.height_px)
                      : cairo_pdf_surface_create_for_stream(append_bytes, &bytes, camera.width_px,
                                                            camera.height_px));
  check(cairo_surface_status(surface.get()));
  if (format == VectorFormat::kSvg) {
    // Pixels, so that the page is the frame's size in every SVG viewer and rasteriser.
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
  }
  Context context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  const Page page{cr, camera};
  if (settings.background.channels[3] > 0.f) {
    set_colour(cr, settings.background);
    cairo_paint(cr);
  }

  std::vector<DetailOutline> outlines;
  const auto placed = placed_outlines(looks, settings, frame, page, outlines);
  const double scale = std::max(1.0, camera.height_px / 720.0);
  const bool by_lambda = settings.overlays.rugosity;
  const double width = settings.outline_px * scale * (by_lambda ? 2.0 : 1.0);
  // Fills first, then outlines, then overlays: the GL renderer's order.
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  for (std::size_t b = 0; b < looks.size(); ++b) {
    if (off_page(placed[b], width, camera)) continue;
    polygon_path(cr, placed[b]);
    set_colour(cr, looks[b].fill);
    cairo_fill(cr);
  }
  std::vector<ToleranceProfile> profiles;
  double largest = 0.0;
  for (const BodyLook& look : looks) {
    profiles.emplace_back(look.lambda);
    largest = std::max(largest, profiles.back().range().hi);
  }
  cairo_set_line_width(cr, width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (std::size_t b = 0; b < looks.size(); ++b) {
    if (off_page(placed[b], width, camera)) continue;
    if (by_lambda) {
      stroke_by_lambda(cr, placed[b], outlines[b], profiles[b], looks[b].curve.size(), largest);
    } else {
      polygon_path(cr, placed[b]);
      set_colour(cr, looks[b].outline.value_or(outline_colour(looks[b].fill)));
      cairo_stroke(cr);
    }
  }
  if (settings.overlays.contacts || settings.overlays.velocity) {
    OverlayBuilder overlays(camera, 0.f, static_cast<float>(scale), false);
    std::vector<bool> fixed;
    for (const BodyLook& look : looks)
      fixed.push_back(look.fixed);
    overlays.add_frame(frame, fixed, settings.overlays);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
    for (const OverlayShape& s : overlays.shapes()) {
      const double x = 0.5 * camera.width_px + s.from.x();
      const double y = 0.5 * camera.height_px - s.from.y();
      set_colour(cr, s.colour);
      cairo_new_path(cr);
      if (s.disc) {
        cairo_arc(cr, x, y, s.half_width, 0.0, 2.0 * M_PI);
        cairo_fill(cr);
      } else {
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, 0.5 * camera.width_px + s.to.x(), 0.5 * camera.height_px - s.to.y());
        cairo_set_line_width(cr, 2.0 * s.half_width);
        cairo_stroke(cr);
      }
    }
  }
  if (text.any()) {
    FrameTextPainter painter(text);
    CairoTextCanvas canvas(cr, camera.width_px, camera.height_px);
    painter.paint(canvas, frame.time, camera.pixel_size());
  }
  check(cairo_status(cr));
  context.reset();
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()));
  return bytes;
}

}  // namespace rugosim
