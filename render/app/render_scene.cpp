#include "render/app/render_scene.h"

#include <algorithm>
#include <cmath>

#include "engine/core/random.h"
#include "engine/geometry/tolerance_profile.h"
#include "render/draw/palette.h"

namespace rugosim::app {
namespace {

constexpr std::uint64_t kDetailStream = 0x6465'7461'696c;  // "detail": apart from the shapes'

}  // namespace

std::vector<BodyLook> body_looks(const Scene& scene, const World& world) {
  std::vector<BodyLook> looks;
  std::size_t moving = 0;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& body = world.body(i);
    const std::vector<double>& lambda = body.shape().tolerances().segment_tolerances();
    std::vector<double> sigma;
    sigma.reserve(lambda.size());
    for (const double l : lambda)
      sigma.push_back(l / scene.q);
    const BodySpec* spec = i < scene.bodies.size() ? &scene.bodies[i] : nullptr;
    std::optional<Rgba> fill;
    if (spec != nullptr && !spec->color.empty()) fill = parse_hex_color(spec->color);
    const Theme theme = scene_theme(scene);
    if (!fill) fill = default_body_colour(moving, body.fixed(), theme);
    if (!body.fixed()) ++moving;
    const std::optional<Rgba> outline = parse_hex_color(scene.render.outline_color);
    looks.push_back(BodyLook{body.curve(), std::move(sigma), lambda, *fill, body.fixed(),
                             derive_seed(derive_seed(scene.seed, kDetailStream), i),
                             outline ? *outline : theme_outline_colour(*fill, theme)});
  }
  return looks;
}

std::optional<Camera> scene_camera(const Scene& scene, int width_px, int height_px) {
  if (scene.render.camera.automatic || !scene.render.camera.follow.empty()) return std::nullopt;
  Camera camera;
  camera.center = scene.render.camera.center;
  camera.height = scene.render.camera.height;
  camera.width_px = width_px;
  camera.height_px = height_px;
  return camera;
}

Camera follow_camera(const World& world, std::size_t body, double height, int width_px,
                     int height_px) {
  Camera camera;
  camera.width_px = width_px;
  camera.height_px = height_px;
  if (height > 0.0) {
    camera.height = height;
  } else {
    // The curve's hull in its own frame: the body's size whatever its turn.
    const Vec2 extent = world.body(body).curve().hull_bounds().extent();
    camera.height = 4.0 * std::max(extent.x(), extent.y());
  }
  return camera;
}

FrameSnapshot centred_on(FrameSnapshot frame, std::size_t body) {
  if (body >= frame.bodies.size()) return frame;
  const Transform2 shift(0.0, -frame.bodies[body].placement.translation());
  for (BodyPose& pose : frame.bodies)
    pose.placement = shift * pose.placement;
  for (ContactEvent& event : frame.events)
    event.point = shift.apply(event.point);
  return frame;
}

Camera fit_clip_camera(const World& world, const std::vector<FrameSnapshot>& frames, int width_px,
                       int height_px) {
  Aabb bounds;
  for (const FrameSnapshot& frame : frames) {
    for (std::size_t i = 0; i < frame.bodies.size() && i < world.body_count(); ++i) {
      bounds.extend(world.body(i).shape().world_bounds(frame.bodies[i].placement));
    }
  }
  return fit_camera(bounds, width_px, height_px);
}

std::optional<Overlays> parse_overlays(const std::vector<std::string>& names,
                                       std::string* unknown) {
  Overlays overlays;
  for (const std::string& name : names) {
    if (name == "rugosity") {
      overlays.rugosity = true;
    } else if (name == "contacts") {
      overlays.contacts = true;
    } else if (name == "velocity") {
      overlays.velocity = true;
    } else {
      if (unknown != nullptr) *unknown = name;
      return std::nullopt;
    }
  }
  return overlays;
}

bool has_transparent_background(const Scene& scene) {
  return scene.render.background == kTransparentBackground;
}

Theme scene_theme(const Scene& scene) {
  return parse_theme(scene.render.theme).value_or(Theme::kPaper);
}

Rgba scene_background(const Scene& scene) {
  if (has_transparent_background(scene)) return Rgba{{0.f, 0.f, 0.f, 0.f}};
  // The loader accepts only "#rgb", "#rrggbb", "transparent" or nothing (the theme's).
  return parse_hex_color(scene.render.background).value_or(theme_background(scene_theme(scene)));
}

double scene_outline_px(const Scene& scene) {
  return scene.render.outline_width > 0.0 ? scene.render.outline_width : 1.5;
}

DetailSettings scene_detail(const Scene& scene) {
  DetailSettings detail;
  detail.roughness_scale = scene.render.roughness_scale;
  detail.correlation_length = scene.render.roughness_length;
  return detail;
}

FrameText frame_text(const Scene& scene) {
  const RenderSpec& r = scene.render;
  FrameText text;
  const Rgba colour = theme_text_colour(scene_theme(scene));
  for (std::size_t c = 0; c < 4; ++c)
    text.colour[c] = static_cast<std::uint8_t>(std::lround(colour.channels[c] * 255.f));
  text.title = r.title;
  text.caption = r.caption;
  if (r.clock) {
    text.clock = true;
    text.clock_corner = parse_corner(r.clock->corner).value_or(Corner::kTopLeft);
    text.clock_format = r.clock->format;
  }
  if (r.scale_bar) {
    text.scale_bar = true;
    text.scale_bar_corner = parse_corner(r.scale_bar->corner).value_or(Corner::kBottomLeft);
    text.scale_bar_length = r.scale_bar->length;
  }
  return text;
}

FrameText frame_text(const Scene& scene, const std::vector<BodyLook>& looks,
                     const Overlays& overlays) {
  FrameText text = frame_text(scene);
  if (scene.render.colour_bar && overlays.rugosity) {
    text.colour_bar = true;
    text.colour_bar_corner =
        parse_corner(scene.render.colour_bar->corner).value_or(Corner::kBottomRight);
    // The largest λ as the renderer scales the overlay's colours (scene_renderer.cpp).
    for (const BodyLook& look : looks) {
      text.largest_lambda = std::max(text.largest_lambda, ToleranceProfile(look.lambda).range().hi);
    }
  }
  return text;
}

}  // namespace rugosim::app
