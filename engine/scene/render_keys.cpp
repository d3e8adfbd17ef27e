#include "engine/scene/render_keys.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "engine/scene/scene_loader.h"

namespace rugosim::scene_json {
namespace {

// Upper bounds that keep a typo from asking for terabytes; far above any sensible scene.
constexpr int kMaxImageSide = 16384;  // px
constexpr double kMaxFps = 1000.0;

// One of kCorners.
void read_corner(Reader& r, const json& v, const std::string& path, std::string& corner) {
  r.string(v, path, corner);
  if (!v.is_string()) return;
  for (const char* known : kCorners) {
    if (corner == known) return;
  }
  r.error(path, "expected \"top-left\", \"top-right\", \"bottom-left\" or \"bottom-right\", got " +
                    shown(v));
}

// A clock format: text with exactly one conversion %f or %.Nf (N a digit), "%%" for a percent
// sign. Anything else (%s, %d, two numbers) would let printf read what is not there.
bool is_clock_format(const std::string& format) {
  int conversions = 0;
  for (std::size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%') continue;
    if (i + 1 < format.size() && format[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    if (j + 1 < format.size() && format[j] == '.' &&
        std::isdigit(static_cast<unsigned char>(format[j + 1]))) {
      j += 2;
    }
    if (j >= format.size() || format[j] != 'f') return false;
    ++conversions;
    i = j;
  }
  return conversions == 1 && format.size() <= 200;
}

// render.clock: true (the defaults), false (none), or {"corner", "format"}.
void read_clock(Reader& r, const json& v, const std::string& path, std::optional<ClockSpec>& out) {
  if (v.is_boolean()) {
    if (v.get<bool>()) out = ClockSpec{};
    return;
  }
  if (!v.is_object()) {
    r.error(path, "expected true, false or {\"corner\": ..., \"format\": \"t = %.2f s\"}, got " +
                      shown(v));
    return;
  }
  r.check_keys(v, path, {"corner", "format"});
  ClockSpec clock;
  if (v.contains("corner")) read_corner(r, v["corner"], child(path, "corner"), clock.corner);
  if (v.contains("format")) {
    r.string(v["format"], child(path, "format"), clock.format);
    if (v["format"].is_string() && !is_clock_format(clock.format)) {
      r.error(child(path, "format"),
              "expected text with one %f or %.Nf for the time in seconds (e.g. \"t = %.2f s\"; "
              "%% for a percent sign), got " +
                  shown(v["format"]));
    }
  }
  out = clock;
}

// render.scale_bar: true (the defaults), false (none), or {"corner", "length"}.
void read_scale_bar(Reader& r, const json& v, const std::string& path,
                    std::optional<ScaleBarSpec>& out) {
  if (v.is_boolean()) {
    if (v.get<bool>()) out = ScaleBarSpec{};
    return;
  }
  if (!v.is_object()) {
    r.error(path, "expected true, false or {\"corner\": ..., \"length\": metres}, got " + shown(v));
    return;
  }
  r.check_keys(v, path, {"corner", "length"});
  ScaleBarSpec bar;
  if (v.contains("corner")) read_corner(r, v["corner"], child(path, "corner"), bar.corner);
  if (v.contains("length")) r.positive(v["length"], child(path, "length"), bar.length, "m");
  out = bar;
}

}  // namespace

// A colour: "#rrggbb" or "#rgb", or the word `also` where one is allowed.
void read_colour(Reader& r, const json& v, const std::string& path, std::string& colour,
                 const char* also) {
  r.string(v, path, colour);
  const bool hex = (colour.size() == 7 || colour.size() == 4) && colour[0] == '#' &&
                   std::all_of(colour.begin() + 1, colour.end(),
                               [](char d) { return std::isxdigit(static_cast<unsigned char>(d)); });
  if (v.is_string() && !hex && (also == nullptr || colour != also)) {
    r.error(path, std::string("expected a colour \"#rrggbb\" or \"#rgb\"") +
                      (also != nullptr ? std::string(", or \"") + also + "\"" : std::string()) +
                      ", got " + shown(v));
  }
}

void read_render(Reader& r, const json& v, const std::string& path, RenderSpec& render) {
  if (!r.is_object(v, path)) return;
  r.check_keys(
      v, path,
      {"size", "fps", "camera", "background", "overlays", "title", "caption", "clock", "scale_bar",
       "colour_bar", "theme", "outline", "roughness_scale", "roughness_length"});
  if (v.contains("roughness_scale")) {
    r.ranged(v["roughness_scale"], child(path, "roughness_scale"), render.roughness_scale, 0.0,
             false, 100.0, false, "a number in [0, 100] (display-only: 0 draws smooth outlines)");
  }
  if (v.contains("roughness_length")) {
    r.ranged(v["roughness_length"], child(path, "roughness_length"), render.roughness_length, 0.0,
             true, 1e6, false, "a length in metres in (0, 1e6]");
  }
  if (v.contains("colour_bar")) {
    const json& bar = v["colour_bar"];
    const std::string at = child(path, "colour_bar");
    if (bar.is_boolean()) {
      if (bar.get<bool>()) render.colour_bar = ColourBarSpec{};
    } else if (bar.is_object()) {
      r.check_keys(bar, at, {"corner"});
      ColourBarSpec spec;
      if (bar.contains("corner")) read_corner(r, bar["corner"], child(at, "corner"), spec.corner);
      render.colour_bar = spec;
    } else {
      r.error(at, "expected true, false or {\"corner\": ...}, got " + shown(bar));
    }
  }
  if (v.contains("theme")) {
    r.string(v["theme"], child(path, "theme"), render.theme);
    if (v["theme"].is_string() && render.theme != "paper" && render.theme != "dark" &&
        render.theme != "print") {
      r.error(child(path, "theme"),
              "expected \"paper\", \"dark\" or \"print\", got " + shown(v["theme"]));
    }
  }
  if (v.contains("outline")) {
    const json& outline = v["outline"];
    const std::string at = child(path, "outline");
    if (r.is_object(outline, at)) {
      r.check_keys(outline, at, {"color", "width"});
      if (outline.contains("color")) {
        read_colour(r, outline["color"], child(at, "color"), render.outline_color);
      }
      if (outline.contains("width")) {
        r.ranged(outline["width"], child(at, "width"), render.outline_width, 0.0, true, 100.0,
                 false, "a number in (0, 100] (px at 720 lines)");
      }
    }
  }
  if (v.contains("title")) r.string(v["title"], child(path, "title"), render.title);
  if (v.contains("caption")) r.string(v["caption"], child(path, "caption"), render.caption);
  if (v.contains("clock")) read_clock(r, v["clock"], child(path, "clock"), render.clock);
  if (v.contains("scale_bar")) {
    read_scale_bar(r, v["scale_bar"], child(path, "scale_bar"), render.scale_bar);
  }
  if (v.contains("size")) {
    const json& size = v["size"];
    const std::string at = child(path, "size");
    if (!size.is_array() || size.size() != 2) {
      r.error(at, "expected [width, height] in pixels, got " + shown(size));
    } else {
      std::size_t w = 0, h = 0;
      const auto side = static_cast<std::size_t>(kMaxImageSide);
      r.count(size[0], child(at, 0), w, 1, side, "pixels");
      r.count(size[1], child(at, 1), h, 1, side, "pixels");
      render.width = static_cast<int>(w);
      render.height = static_cast<int>(h);
    }
  }
  if (v.contains("fps")) {
    r.ranged(v["fps"], child(path, "fps"), render.fps, 0.0, true, kMaxFps, false,
             "a number in (0, 1000] (frames per second)");
  }
  if (v.contains("camera")) {
    const json& camera = v["camera"];
    const std::string at = child(path, "camera");
    if (camera.is_string() && camera.get<std::string>() == "auto") {
      render.camera.automatic = true;
    } else if (camera.is_object()) {
      render.camera.automatic = false;
      r.check_keys(camera, at, {"center", "height", "follow"});
      const bool follows = camera.contains("follow");
      if (follows) {
        r.string(camera["follow"], child(at, "follow"), render.camera.follow);
        if (camera["follow"].is_string() && render.camera.follow.empty()) {
          r.error(child(at, "follow"), "expected a body's name, got \"\"");
        }
        if (camera.contains("center")) {
          r.error(child(at, "center"), "a camera that follows a body has no fixed centre");
        }
      } else if (camera.contains("center")) {
        r.vec2(camera["center"], child(at, "center"), render.camera.center);
      } else {
        r.error(child(at, "center"), "missing required key \"center\" (or \"follow\")");
      }
      if (camera.contains("height")) {
        r.positive(camera["height"], child(at, "height"), render.camera.height, "m");
      } else if (!follows) {
        r.error(child(at, "height"), "missing required key \"height\"");
      }
    } else {
      r.error(at,
              "expected \"auto\", {\"center\": [x, y], \"height\": h} or {\"follow\": "
              "BODY}, got " +
                  shown(camera));
    }
  }
  if (v.contains("background")) {
    read_colour(r, v["background"], child(path, "background"), render.background,
                kTransparentBackground);
  }
  if (v.contains("overlays")) {
    const json& overlays = v["overlays"];
    const std::string at = child(path, "overlays");
    static const std::vector<std::string> known = {"rugosity", "contacts", "velocity"};
    if (!overlays.is_array()) {
      r.error(at, "expected an array of overlay names, got " + shown(overlays));
    } else {
      for (std::size_t i = 0; i < overlays.size(); ++i) {
        std::string name;
        r.string(overlays[i], child(at, i), name);
        if (!overlays[i].is_string()) continue;
        if (std::find(known.begin(), known.end(), name) == known.end()) {
          std::string message = "unknown overlay \"" + name +
                                "\"; expected \"rugosity\", \"contacts\" or \"velocity\"";
          const std::string suggestion = closest_match(name, known);
          if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
          r.error(child(at, i), message);
        } else {
          render.overlays.push_back(name);
        }
      }
    }
  }
}

}  // namespace rugosim::scene_json
