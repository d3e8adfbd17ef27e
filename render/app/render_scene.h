// From a loaded scene to what the renderer needs: how each body looks (its curve, σ and λ,
// colour, detail seed) and the camera of a clip (the scene's, or `auto`: every body over every
// frame of the clip, fitted).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/dynamics/frame_snapshot.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"
#include "render/draw/camera.h"
#include "render/draw/overlay_geometry.h"
#include "render/draw/palette.h"
#include "render/draw/scene_renderer.h"
#include "render/text/frame_text.h"

namespace rugosim::app {

// One look per body of the World, in its order: the scene's colour or the default palette,
// σ = λ / q per segment of the body's stored curve, a detail seed from the scene's seed.
std::vector<BodyLook> body_looks(const Scene& scene, const World& world);

// The explicit camera of the scene's render.camera, or nullopt for "auto" (and for "follow",
// whose camera is follow_camera's).
std::optional<Camera> scene_camera(const Scene& scene, int width_px, int height_px);
// The camera of render.camera.follow: centred on the origin, where centred_on() puts the body,
// `height` m high, or 4 × the body's larger side when `height` is 0.
Camera follow_camera(const World& world, std::size_t body, double height, int width_px,
                     int height_px);
// The frame moved so that `body`'s centre of mass is at the origin: every placement and event
// point shifted by the same offset (exactly: a translation composed with each placement).
FrameSnapshot centred_on(FrameSnapshot frame, std::size_t body);

// render.theme (palette.h).
Theme scene_theme(const Scene& scene);
// render.background as the renderer takes it: the colour (the theme's when the scene names
// none), or (0, 0, 0, 0) for "transparent".
Rgba scene_background(const Scene& scene);
// render.outline.width: px at 720 lines.
double scene_outline_px(const Scene& scene);
// render.roughness_scale and render.roughness_length as detail settings (pixel size unset).
DetailSettings scene_detail(const Scene& scene);

// render.title, caption, clock and scale_bar as the text painter takes them.
FrameText frame_text(const Scene& scene);
// The same, with render.colour_bar when the rugosity overlay is drawn (its range from `looks`).
FrameText frame_text(const Scene& scene, const std::vector<BodyLook>& looks,
                     const Overlays& overlays);
bool has_transparent_background(const Scene& scene);

// The camera that shows every body in every snapshot (their bands included).
Camera fit_clip_camera(const World& world, const std::vector<FrameSnapshot>& frames, int width_px,
                       int height_px);

// Overlay names ("rugosity", "contacts", "velocity"); nullopt names the first unknown one in
// `unknown`.
std::optional<Overlays> parse_overlays(const std::vector<std::string>& names, std::string* unknown);

}  // namespace rugosim::app
