#include "engine/scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

#include <nlohmann/json.hpp>

#include "engine/dynamics/accuracy.h"
#include "engine/geometry/shapes.h"
#include "engine/scene/json_reader.h"
#include "engine/scene/render_keys.h"

namespace rugosim {
namespace {

using namespace scene_json;

// Upper bounds that keep a typo from asking for terabytes; far above any sensible scene.
constexpr std::size_t kMaxSegments = 100000;
constexpr std::size_t kMinSegments = 4;

Material read_material(Reader& r, const json& v, const std::string& path) {
  Material m;
  if (!r.is_object(v, path)) return m;
  r.check_keys(v, path, {"density", "restitution", "restitution_max", "lambda_min"});
  if (v.contains("density")) r.positive(v["density"], child(path, "density"), m.density, "kg/m²");
  if (v.contains("restitution")) {
    r.ranged(v["restitution"], child(path, "restitution"), m.restitution, 0.0, false, 1.0, false,
             "a number in [0, 1]");
  }
  // Unset, ε_max follows ε up: max(ε, the default 0.5), so setting only a bouncier ε is valid.
  m.restitution_max = std::max(m.restitution, Material::kDefaultRestitutionMax);
  if (v.contains("restitution_max")) {
    double eps_max = m.restitution_max;
    r.ranged(v["restitution_max"], child(path, "restitution_max"), eps_max, 0.0, false, 1.0, false,
             "a number in [0, 1]");
    if (eps_max < m.restitution) {
      // Without "restitution" the bound is its default: name that, since v["restitution"] on a
      // const object without the key is undefined behaviour (found by fuzzing).
      const std::string bound = v.contains("restitution")
                                    ? shown(v["restitution"])
                                    : "the default " + shown(json(m.restitution));
      r.error(child(path, "restitution_max"), "expected restitution_max >= restitution (" + bound +
                                                  "), got " + shown(v["restitution_max"]));
    }
    m.restitution_max = eps_max;
  }
  if (v.contains("lambda_min")) {
    r.ranged(v["lambda_min"], child(path, "lambda_min"), m.lambda_min, 0.0, false,
             std::numeric_limits<double>::infinity(), true, "a number >= 0 (m)");
  }
  return m;
}

// The segment count a shape will have, for checking a σ list; 0 when the shape is invalid.
std::size_t read_shape(Reader& r, const json& v, const std::string& path, ShapeSpec& shape) {
  static const std::vector<std::string> kinds = {"control_points", "circle", "ellipse", "box",
                                                 "blob",           "polygon"};
  if (!r.is_object(v, path)) return 0;
  if (v.size() != 1) {
    r.error(path,
            "expected exactly one of \"control_points\", \"circle\", \"ellipse\", "
            "\"box\", \"blob\", \"polygon\", got " +
                std::to_string(v.size()) + " keys");
    r.check_keys(v, path, kinds);
    return 0;
  }
  const std::string kind = v.begin().key();
  const json& spec = v.begin().value();
  const std::string at = child(path, kind);
  if (kind == "control_points") {
    shape.kind = ShapeKind::kControlPoints;
    if (!spec.is_array() || spec.size() < kMinSegments || spec.size() > kMaxSegments) {
      r.error(at, "expected an array of 4 to " + std::to_string(kMaxSegments) +
                      " points [x, y], got " +
                      (spec.is_array() ? std::to_string(spec.size()) + " points" : shown(spec)));
      return 0;
    }
    for (std::size_t i = 0; i < spec.size(); ++i) {
      Vec2 p = Vec2::Zero();
      r.vec2(spec[i], child(at, i), p);
      shape.control_points.push_back(p);
    }
    shape.segments = spec.size();
    return spec.size();
  }
  if (!r.is_object(spec, at)) return 0;
  auto segments = [&]() {
    if (spec.contains("segments")) {
      r.count(spec["segments"], child(at, "segments"), shape.segments, kMinSegments, kMaxSegments,
              "B-spline segments");
    }
  };
  auto required = [&](const char* key) -> const json* {
    if (spec.contains(key)) return &spec[key];
    r.error(child(at, key), std::string("missing required key \"") + key + "\"");
    return nullptr;
  };
  if (kind == "circle") {
    shape.kind = ShapeKind::kCircle;
    r.check_keys(spec, at, {"radius", "segments"});
    if (const json* radius = required("radius"))
      r.positive(*radius, child(at, "radius"), shape.radius, "m");
    segments();
  } else if (kind == "ellipse") {
    shape.kind = ShapeKind::kEllipse;
    r.check_keys(spec, at, {"radii", "segments"});
    if (const json* radii = required("radii")) {
      r.vec2(*radii, child(at, "radii"), shape.radii);
      if (radii->is_array() && radii->size() == 2 &&
          !(shape.radii.x() > 0.0 && shape.radii.y() > 0.0)) {
        r.error(child(at, "radii"), "expected two radii > 0 (m), got " + shown(*radii));
      }
    }
    segments();
  } else if (kind == "box") {
    shape.kind = ShapeKind::kBox;
    r.check_keys(spec, at, {"size", "segments"});
    if (const json* size = required("size")) {
      r.vec2(*size, child(at, "size"), shape.size);
      if (size->is_array() && size->size() == 2 &&
          !(shape.size.x() > 0.0 && shape.size.y() > 0.0)) {
        r.error(child(at, "size"), "expected a width and a height > 0 (m), got " + shown(*size));
      }
    }
    segments();
  } else if (kind == "polygon") {
    shape.kind = ShapeKind::kPolygon;
    r.check_keys(spec, at, {"points", "rounding", "segments"});
    const json* points = required("points");
    if (points == nullptr) return 0;
    const std::string points_at = child(at, "points");
    if (!points->is_array() || points->size() < 3 || points->size() > kMaxSegments / 3) {
      r.error(points_at, "expected an array of 3 to " + std::to_string(kMaxSegments / 3) +
                             " corners [x, y], got " +
                             (points->is_array() ? std::to_string(points->size()) + " corners"
                                                 : shown(*points)));
      return 0;
    }
    for (std::size_t i = 0; i < points->size(); ++i) {
      Vec2 p = Vec2::Zero();
      r.vec2((*points)[i], child(points_at, i), p);
      shape.control_points.push_back(p);
    }
    const std::size_t corners = shape.control_points.size();
    for (std::size_t i = 0; i < corners; ++i) {
      if (shape.control_points[i] == shape.control_points[(i + 1) % corners]) {
        r.error(child(points_at, (i + 1) % corners),
                "a corner equal to the one before it; expected distinct neighbours");
      }
    }
    if (spec.contains("rounding")) {
      const json& rounding = spec["rounding"];
      const std::string rounding_at = child(at, "rounding");
      if (rounding.is_array()) {
        if (rounding.size() != corners) {
          r.error(rounding_at, "expected one length per corner (" + std::to_string(corners) +
                                   "), got " + std::to_string(rounding.size()));
        }
        for (std::size_t i = 0; i < rounding.size(); ++i) {
          double x = 0.0;
          r.ranged(rounding[i], child(rounding_at, i), x, 0.0, false,
                   std::numeric_limits<double>::infinity(), true, "a length >= 0 (m)");
          shape.rounding.push_back(x);
        }
      } else {
        double x = 0.0;
        r.ranged(rounding, rounding_at, x, 0.0, false, std::numeric_limits<double>::infinity(),
                 true, "a length >= 0 (m), or one per corner");
        shape.rounding.assign(corners, x);
      }
      // At most half of each edge beside the corner, so that roundings never overlap.
      for (std::size_t i = 0; i < shape.rounding.size() && i < corners; ++i) {
        const Vec2& c = shape.control_points[i];
        const double room =
            0.5 * std::min((shape.control_points[(i + 1) % corners] - c).norm(),
                           (c - shape.control_points[(i + corners - 1) % corners]).norm());
        if (shape.rounding[i] > room) {
          r.error(rounding.is_array() ? child(rounding_at, i) : rounding_at,
                  "corner " + std::to_string(i) + ": expected at most " + shown(json(room)) +
                      " m (half its shorter edge), got " + shown(json(shape.rounding[i])));
        }
      }
    }
    shape.segments = std::max(SceneDefaults::kSegments, 3 * corners);
    if (spec.contains("segments")) {
      r.count(spec["segments"], child(at, "segments"), shape.segments, 3 * corners, kMaxSegments,
              "B-spline segments (at least 3 per corner)");
    }
  } else if (kind == "blob") {
    shape.kind = ShapeKind::kBlob;
    r.check_keys(spec, at, {"radius", "irregularity", "segments", "seed"});
    if (const json* radius = required("radius"))
      r.positive(*radius, child(at, "radius"), shape.radius, "m");
    if (spec.contains("irregularity")) {
      r.ranged(spec["irregularity"], child(at, "irregularity"), shape.irregularity, 0.0, false,
               kMaxBlobIrregularity, false, "a number in [0, 0.9]");
    }
    if (spec.contains("seed")) r.seed(spec["seed"], child(at, "seed"), shape.seed);
    segments();
  } else {
    std::string message = "unknown shape \"" + kind +
                          "\"; expected one of \"control_points\", "
                          "\"circle\", \"ellipse\", \"box\", \"blob\", \"polygon\"";
    const std::string suggestion = closest_match(kind, kinds);
    if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
    r.error(at, message);
    return 0;
  }
  return shape.segments;
}

void read_rugosity(Reader& r, const json& v, const std::string& path, std::size_t segments,
                   RugositySpec& rugosity) {
  if (!r.is_object(v, path)) return;
  r.check_keys(v, path, {"pattern", "sigma"});
  const std::string sigma_path = child(path, "sigma");
  if (v.contains("pattern")) {
    std::string name;
    r.string(v["pattern"], child(path, "pattern"), name);
    if (v["pattern"].is_string()) {
      rugosity.pattern = parse_rugosity_pattern(name);
      if (!rugosity.pattern) {
        std::string message = "unknown pattern \"" + name +
                              "\"; expected one of \"type_1\", "
                              "\"type_2\", \"type_3\", \"type_4\"";
        const std::string suggestion =
            closest_match(name, {"type_1", "type_2", "type_3", "type_4"});
        if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
        r.error(child(path, "pattern"), message);
      }
    }
    if (!v.contains("sigma")) {
      r.error(sigma_path, "missing required key \"sigma\" (the pattern's largest σ, m)");
    } else if (!v["sigma"].is_number()) {
      r.error(sigma_path,
              "expected one number >= 0 (m) to scale the pattern, got " + shown(v["sigma"]));
    }
  }
  if (!v.contains("sigma")) return;
  const json& sigma = v["sigma"];
  const std::string expectation = "a number >= 0 (m)";
  if (sigma.is_array()) {
    if (segments != 0 && sigma.size() != segments) {
      r.error(sigma_path, "expected " + std::to_string(segments) +
                              " values, one per segment, got " + std::to_string(sigma.size()));
      return;
    }
    for (std::size_t i = 0; i < sigma.size(); ++i) {
      double s = 0.0;
      r.ranged(sigma[i], child(sigma_path, i), s, 0.0, false,
               std::numeric_limits<double>::infinity(), true, expectation);
      rugosity.sigma.push_back(s);
    }
  } else if (sigma.is_number()) {
    double s = 0.0;
    r.ranged(sigma, sigma_path, s, 0.0, false, std::numeric_limits<double>::infinity(), true,
             expectation);
    rugosity.sigma.push_back(s);
  } else if (!v.contains("pattern")) {
    r.error(sigma_path, "expected a number >= 0 (m) or one per segment, got " + shown(sigma));
  }
}

void read_body(Reader& r, const json& v, const std::string& path, const Scene& scene,
               BodySpec& body) {
  if (!r.is_object(v, path)) return;
  r.check_keys(v, path,
               {"name", "fixed", "shape", "position", "angle", "velocity", "angular_velocity",
                "material", "rugosity", "color"});
  if (v.contains("name")) {
    r.string(v["name"], child(path, "name"), body.name);
    if (v["name"].is_string() && body.name.empty()) {
      r.error(child(path, "name"), "expected a non-empty name");
    }
  } else {
    r.error(child(path, "name"), "missing required key \"name\"");
  }
  if (v.contains("fixed")) r.boolean(v["fixed"], child(path, "fixed"), body.fixed);
  std::size_t segments = 0;
  if (v.contains("shape")) {
    segments = read_shape(r, v["shape"], child(path, "shape"), body.shape);
  } else {
    r.error(child(path, "shape"), "missing required key \"shape\"");
  }
  if (v.contains("position")) r.vec2(v["position"], child(path, "position"), body.position);
  if (v.contains("angle")) r.number(v["angle"], child(path, "angle"), body.angle);
  if (v.contains("velocity")) r.vec2(v["velocity"], child(path, "velocity"), body.velocity);
  if (v.contains("angular_velocity")) {
    r.number(v["angular_velocity"], child(path, "angular_velocity"), body.angular_velocity);
  }
  if (body.fixed && (v.contains("velocity") || v.contains("angular_velocity")) &&
      (body.velocity != Vec2::Zero() || body.angular_velocity != 0.0)) {
    r.error(child(path, v.contains("velocity") ? "velocity" : "angular_velocity"),
            "a fixed body cannot move: expected no velocity");
  }
  if (v.contains("material")) {
    const json& m = v["material"];
    const std::string at = child(path, "material");
    if (m.is_string()) {
      body.material_name = m.get<std::string>();
      const auto found = scene.materials.find(body.material_name);
      if (found != scene.materials.end()) {
        body.material = found->second;
      } else {
        std::vector<std::string> names;
        for (const auto& [name, material] : scene.materials)
          names.push_back(name);
        std::string message = "unknown material \"" + body.material_name + "\"";
        message += names.empty() ? "; the scene defines no \"materials\""
                                 : "; expected a name defined in /materials";
        const std::string suggestion = closest_match(body.material_name, names);
        if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
        r.error(at, message);
      }
    } else if (m.is_object()) {
      body.material = read_material(r, m, at);
    } else {
      r.error(at, "expected a material name or an object, got " + shown(m));
    }
  }
  if (v.contains("rugosity")) {
    read_rugosity(r, v["rugosity"], child(path, "rugosity"), segments, body.rugosity);
  }
  if (v.contains("color")) read_colour(r, v["color"], child(path, "color"), body.color);
}

// "a", "b" or "c"
std::string quoted_list(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += i + 1 == words.size() ? " or " : ", ";
    out += "\"" + words[i] + "\"";
  }
  return out;
}

void read_preset(Reader& r, const json& v, const std::string& path, std::string& preset) {
  r.string(v, path, preset);
  const std::vector<std::string>& presets = accuracy_preset_names();
  if (v.is_string() && std::find(presets.begin(), presets.end(), preset) == presets.end()) {
    std::string message = "expected " + quoted_list(presets) + ", got " + shown(v);
    const std::string suggestion = closest_match(preset, presets);
    if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
    r.error(path, message);
  }
}

// "accuracy": a preset's name, or {"preset": name, knob: value, ...} (engine/dynamics/accuracy.h).
void read_accuracy(Reader& r, const json& v, const std::string& path, Scene& scene) {
  if (v.is_string()) {
    read_preset(r, v, path, scene.accuracy.preset);
    return;
  }
  if (!v.is_object()) {
    r.error(path,
            "expected a preset (\"draft\", \"normal\" or \"precise\") or an object of "
            "accuracy knobs, got " +
                shown(v));
    return;
  }
  std::vector<std::string> keys = {"preset"};
  for (const AccuracyKnob& knob : accuracy_knobs())
    keys.emplace_back(knob.key);
  r.check_keys(v, path, keys);
  if (v.contains("preset"))
    read_preset(r, v["preset"], child(path, "preset"), scene.accuracy.preset);
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    const std::string key(knob.key);
    if (!v.contains(key)) continue;
    const json& value = v[key];
    const std::string at = child(path, key);
    if (!value.is_number() || (knob.integer && !value.is_number_integer()) ||
        !knob.valid(value.get<double>())) {
      r.error(at, "expected " + knob.expectation() + ", got " + shown(value));
      continue;
    }
    scene.accuracy.knobs[key] = value.get<double>();
  }
  if (const std::optional<Accuracy> preset = accuracy_preset(scene.accuracy.preset)) {
    Accuracy resolved = *preset;
    for (const auto& [key, value] : scene.accuracy.knobs)
      find_accuracy_knob(key)->set(resolved, value);
    if (resolved.toi_tolerance > resolved.max_step) {
      r.error(child(path, v.contains("toi_tolerance") ? "toi_tolerance" : "max_step"),
              "toi_tolerance (" + shown(json(resolved.toi_tolerance)) +
                  " s) must not exceed max_step (" + shown(json(resolved.max_step)) + " s)");
    }
  }
}

void read_world(Reader& r, const json& v, const std::string& path, Scene& scene) {
  if (!r.is_object(v, path)) return;
  r.check_keys(v, path, {"gravity", "duration", "seed", "accuracy", "q", "friction_gain"});
  if (v.contains("gravity")) r.vec2(v["gravity"], child(path, "gravity"), scene.gravity);
  if (v.contains("duration"))
    r.positive(v["duration"], child(path, "duration"), scene.duration, "s");
  if (v.contains("seed")) r.seed(v["seed"], child(path, "seed"), scene.seed);
  if (v.contains("accuracy")) read_accuracy(r, v["accuracy"], child(path, "accuracy"), scene);
  if (v.contains("q")) {
    r.ranged(v["q"], child(path, "q"), scene.q, 0.0, true, 1.0, false, "a number in (0, 1]");
  }
  if (v.contains("friction_gain")) {
    r.ranged(v["friction_gain"], child(path, "friction_gain"), scene.friction_gain, 0.0, false,
             std::numeric_limits<double>::infinity(), true, "a number >= 0 (1/m)");
  }
}

}  // namespace

std::optional<std::size_t> find_body(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].name == name) return i;
  }
  return std::nullopt;
}

std::string unknown_body_message(const Scene& scene, const std::string& name) {
  std::vector<std::string> names;
  for (const BodySpec& body : scene.bodies) {
    if (!body.name.empty()) names.push_back(body.name);
  }
  std::string message = "no body named \"" + name + "\"";
  const std::string suggestion = closest_match(name, names);
  if (!suggestion.empty()) message += " (did you mean \"" + suggestion + "\"?)";
  if (names.empty()) message += "; the scene's bodies have no \"name\"";
  return message;
}

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  const std::size_t allowed = std::max<std::size_t>(1, (word.size() + 2) / 3);
  return best_distance >= 1 && best_distance <= allowed ? best : std::string();
}

SceneLoad parse_scene(std::string_view text, const std::string& file) {
  SceneLoad load;
  Reader r(file, load.errors);
  const std::optional<json> parsed = parse_json_text(text, file, load.errors);
  if (!parsed) return load;
  const json& root = *parsed;
  Scene& scene = load.scene;
  if (!r.is_object(root, "")) return load;
  r.check_keys(root, "", {"version", "name", "world", "materials", "bodies", "render"});
  if (root.contains("version")) {
    const json& version = root["version"];
    if (!version.is_number_integer() || version.get<std::int64_t>() != 1) {
      r.error("/version", "expected 1 (the only scene format version), got " + shown(version));
    }
  }
  if (root.contains("name")) r.string(root["name"], "/name", scene.name);
  if (scene.name.empty()) scene.name = std::filesystem::path(file).stem().string();
  if (root.contains("world")) {
    read_world(r, root["world"], "/world", scene);
  } else {
    r.error("/world", "missing required key \"world\" (at least its \"duration\")");
  }
  if (root.contains("world") && root["world"].is_object() && !root["world"].contains("duration")) {
    r.error("/world/duration", "missing required key \"duration\" (s, > 0)");
  }
  if (root.contains("materials")) {
    const json& materials = root["materials"];
    if (r.is_object(materials, "/materials")) {
      for (const auto& [name, value] : materials.items())
        scene.materials[name] = read_material(r, value, child("/materials", name));
    }
  }
  if (!root.contains("bodies")) {
    r.error("/bodies", "missing required key \"bodies\" (an array of at least one body)");
  } else if (!root["bodies"].is_array() || root["bodies"].empty()) {
    r.error("/bodies", "expected an array of at least one body, got " + shown(root["bodies"]));
  } else {
    const json& bodies = root["bodies"];
    std::map<std::string, std::size_t> first_with_name;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      BodySpec body;
      read_body(r, bodies[i], child("/bodies", i), scene, body);
      if (!body.name.empty()) {
        const auto [it, inserted] = first_with_name.emplace(body.name, i);
        if (!inserted) {
          r.error(child(child("/bodies", i), "name"),
                  "duplicate body name \"" + body.name + "\" (also /bodies/" +
                      std::to_string(it->second) + "/name); names must be unique");
        }
      }
      scene.bodies.push_back(std::move(body));
    }
  }
  if (root.contains("render")) read_render(r, root["render"], "/render", scene.render);
  const std::string& followed = scene.render.camera.follow;
  if (!followed.empty() && !find_body(scene, followed)) {
    r.error("/render/camera/follow", unknown_body_message(scene, followed));
  }
  return load;
}

SceneLoad load_scene_file(const std::string& path) {
  SceneLoad load;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    load.errors.push_back({path, "", "no such file", 0, 0});
    return load;
  }
  if (std::filesystem::is_directory(path, ec)) {
    load.errors.push_back({path, "", "is a directory, expected a scene file (JSON)", 0, 0});
    return load;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    load.errors.push_back({path, "", "cannot be read", 0, 0});
    return load;
  }
  return parse_scene(text.str(), path);
}

}  // namespace rugosim
