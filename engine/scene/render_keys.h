// The scene's "render" object (docs/scene-format.md, "render"): size, fps, camera, theme,
// background, outline, overlays, title, caption, clock and scale bar, read and checked with
// every error reported at its JSON path; and colours, which bodies have too.
#pragma once

#include <string>

#include "engine/scene/json_reader.h"
#include "engine/scene/scene.h"

namespace rugosim::scene_json {

// A colour: "#rrggbb" or "#rgb", or the word `also` where one is allowed (null: none).
void read_colour(Reader& r, const json& v, const std::string& path, std::string& colour,
                 const char* also = nullptr);

void read_render(Reader& r, const json& v, const std::string& path, RenderSpec& render);

}  // namespace rugosim::scene_json
