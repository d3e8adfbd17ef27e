#include "render/app/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "engine/core/hash.h"
#include "engine/scene/json_reader.h"
#include "engine/scene/scene_loader.h"
#include "render/app/sweep_expression.h"

namespace rugosim::app {
namespace {

using nlohmann::json;
using scene_json::child;
using scene_json::Reader;
using scene_json::shown;

constexpr std::size_t kMostTasks = 1000000;
constexpr std::size_t kMostValues = 100000;

const std::vector<std::string> kReductions = {"first", "last",  "mean", "min",
                                              "max",   "delta", "range"};
const std::vector<std::string> kEventReductions = {"first", "last",  "mean", "min",  "max",
                                                   "delta", "range", "sum",  "count"};
const std::vector<std::string> kTrajectoryColumns = {"x",  "y",     "angle",          "vx",
                                                     "vy", "omega", "kinetic_energy", "speed"};
const std::vector<std::string> kEventColumns = {"time", "t_a", "t_b",      "x",        "y",
                                                "nx",   "ny",  "lambda_a", "lambda_b", "mu",
                                                "vn",   "vt",  "jn",       "jt"};
// stats.json's numbers (telemetry.h); the accuracy object is not a measure.
const std::vector<std::string> kStatsKeys = {"steps",
                                             "bisections",
                                             "collisions",
                                             "contacts",
                                             "fallbacks",
                                             "min_step_fallbacks",
                                             "pass_fallbacks",
                                             "rigid_clusters",
                                             "unresolved_states",
                                             "crossing_fallbacks",
                                             "stalled_steps",
                                             "crossings",
                                             "passes",
                                             "islands_slept",
                                             "islands_woken",
                                             "idle_jumps",
                                             "free_steps",
                                             "rest_steps",
                                             "rest_contacts",
                                             "rest_sweeps",
                                             "rest_unconverged",
                                             "rest_withdrawn",
                                             "body_steps",
                                             "sim_time",
                                             "wall_time",
                                             "stalled_time"};

std::string read_file(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  ok = in && !std::filesystem::is_directory(path);
  if (ok) text << in.rdbuf();
  return text.str();
}

// A whole number as a JSON integer (so that a seed or a count may come from an axis or an
// expression, and 100 reads "100", not "100.0"); any other as a double.
json number_value(double x) {
  if (std::abs(x) < 9007199254740992.0 && x == std::floor(x)) return static_cast<std::int64_t>(x);
  return x;
}

// A name the CSV and the expressions can use.
void check_name(Reader& r, const json& v, const std::string& path, std::string& out,
                std::set<std::string>& taken) {
  r.string(v, path, out);
  if (out.empty() && v.is_string()) {
    r.error(path, "expected a name, got \"\"");
  } else if (!out.empty() && !valid_variable_name(out)) {
    r.error(path, fmt::format("expected a name of letters, digits and \"_\" that starts with a "
                              "letter and is not a built-in function or constant, got {}",
                              shown(v)));
  } else if (!out.empty() && (out == "task" || !taken.insert(out).second)) {
    r.error(path, fmt::format("the name \"{}\" is taken (by \"task\", an axis or a measure)", out));
  }
}

// A JSON pointer whose parent exists in the scene (the key itself may be new: a default the
// scene leaves out).
void check_pointer(Reader& r, const json& scene, const std::string& text, const std::string& path) {
  json::json_pointer pointer;
  try {
    pointer = json::json_pointer(text);
  } catch (const json::exception&) {
    r.error(path, fmt::format("expected a JSON pointer into the scene such as "
                              "\"/world/friction_gain\", got \"{}\"",
                              text));
    return;
  }
  if (pointer.empty()) {
    r.error(path,
            "expected a JSON pointer to a value inside the scene, got \"\" (the whole scene)");
    return;
  }
  const json::json_pointer parent = pointer.parent_pointer();
  if (!scene.contains(parent)) {
    r.error(path, fmt::format("the scene has nothing at \"{}\"", parent.to_string()));
    return;
  }
  const json& holder = scene.at(parent);
  if (holder.is_array()) {
    const std::string& last = pointer.back();
    const bool index = !last.empty() && std::all_of(last.begin(), last.end(), ::isdigit);
    if (!index || std::stoull(last) >= holder.size()) {
      r.error(path, fmt::format("\"{}\" is an array of {} values: expected an index below {}",
                                parent.to_string(), holder.size(), holder.size()));
    }
  } else if (!holder.is_object()) {
    r.error(path, fmt::format("\"{}\" is {}, not an object or an array", parent.to_string(),
                              scene_json::type_name(holder)));
  }
}

void read_axis_values(Reader& r, const json& a, const std::string& path, SweepAxis& axis) {
  const int given = int(a.contains("values")) + int(a.contains("range")) + int(a.contains("seeds"));
  if (given != 1) {
    r.error(path, "expected exactly one of \"values\", \"range\" and \"seeds\"");
    return;
  }
  if (a.contains("values")) {
    const json& v = a["values"];
    if (!v.is_array() || v.empty() || v.size() > kMostValues) {
      r.error(child(path, "values"),
              fmt::format("expected an array of 1 to {} values, got {}", kMostValues, shown(v)));
      return;
    }
    for (const json& x : v)
      axis.values.push_back(x);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (v[i].is_number() && !std::isfinite(v[i].get<double>()))
        r.error(child(child(path, "values"), i), "expected a finite number");
    }
  } else if (a.contains("range")) {
    const std::string rp = child(path, "range");
    const json& g = a["range"];
    if (!r.is_object(g, rp)) return;
    r.check_keys(g, rp, {"from", "to", "count", "step"});
    double from = 0.0, to = 0.0;
    const bool ok = g.contains("from") && g.contains("to") &&
                    r.number(g["from"], child(rp, "from"), from) &&
                    r.number(g["to"], child(rp, "to"), to);
    if (!g.contains("from") || !g.contains("to")) r.error(rp, "expected \"from\" and \"to\"");
    if (g.contains("count") == g.contains("step")) {
      r.error(rp,
              "expected one of \"count\" (values from \"from\" to \"to\" inclusive) and "
              "\"step\"");
      return;
    }
    std::size_t count = 0;
    if (g.contains("count")) {
      r.count(g["count"], child(rp, "count"), count, 1, kMostValues, "values");
    } else {
      double step = 0.0;
      r.positive(g["step"], child(rp, "step"), step, "");
      if (ok && step > 0.0) {
        const double n = std::floor(std::abs(to - from) / step + 1e-9) + 1.0;
        if (n > double(kMostValues)) {
          r.error(child(rp, "step"), fmt::format("expected at most {} values", kMostValues));
        } else {
          count = static_cast<std::size_t>(n);
          to = from + std::copysign(step * double(count - 1), to - from);
        }
      }
    }
    if (!ok || count == 0) return;
    for (std::size_t i = 0; i < count; ++i) {
      const double t = count == 1 ? 0.0 : double(i) / double(count - 1);
      // The ends exactly as written; in between, the same formula on every machine.
      axis.values.push_back(
          number_value(i + 1 == count && count > 1 ? to : from + (to - from) * t));
    }
  } else {
    const std::string sp = child(path, "seeds");
    const json& s = a["seeds"];
    if (!r.is_object(s, sp)) return;
    r.check_keys(s, sp, {"first", "count"});
    std::uint64_t first = 0;
    std::size_t count = 0;
    if (s.contains("first")) r.seed(s["first"], child(sp, "first"), first);
    if (!s.contains("count"))
      r.error(sp, "expected \"count\"");
    else
      r.count(s["count"], child(sp, "count"), count, 1, kMostValues, "seeds");
    for (std::size_t i = 0; i < count; ++i)
      axis.values.emplace_back(first + i);
  }
}

void read_measure(Reader& r, const json& m, const std::string& path, const json& scene,
                  SweepMeasure& out, std::set<std::string>& taken) {
  if (!r.is_object(m, path)) return;
  r.check_keys(m, path, {"name", "stats", "trajectory", "events", "expression"});
  if (m.contains("name"))
    check_name(r, m["name"], child(path, "name"), out.name, taken);
  else
    r.error(path, "expected \"name\"");
  const int given = int(m.contains("stats")) + int(m.contains("trajectory")) +
                    int(m.contains("events")) + int(m.contains("expression"));
  if (given != 1) {
    r.error(path,
            "expected exactly one of \"stats\", \"trajectory\", \"events\" and \"expression\"");
    return;
  }
  if (m.contains("stats")) {
    out.source = SweepMeasure::Source::kStats;
    r.string(m["stats"], child(path, "stats"), out.key);
    if (m["stats"].is_string() &&
        std::find(kStatsKeys.begin(), kStatsKeys.end(), out.key) == kStatsKeys.end()) {
      std::string message = fmt::format("stats.json has no number \"{}\"", out.key);
      const std::string suggestion = closest_match(out.key, kStatsKeys);
      if (!suggestion.empty()) message += fmt::format("; did you mean \"{}\"?", suggestion);
      r.error(child(path, "stats"), message);
    }
    return;
  }
  if (m.contains("expression")) {
    out.source = SweepMeasure::Source::kExpression;
    r.string(m["expression"], child(path, "expression"), out.expression);
    return;
  }
  const bool events = m.contains("events");
  out.source = events ? SweepMeasure::Source::kEvents : SweepMeasure::Source::kTrajectory;
  const std::string p = child(path, events ? "events" : "trajectory");
  const json& d = m[events ? "events" : "trajectory"];
  if (!r.is_object(d, p)) return;
  if (events)
    r.check_keys(d, p, {"column", "reduce", "kind", "body", "from", "to"});
  else
    r.check_keys(d, p, {"column", "reduce", "body", "from", "to"});
  const auto& columns = events ? kEventColumns : kTrajectoryColumns;
  const auto& reductions = events ? kEventReductions : kReductions;
  const auto one_of = [&](const char* key, const std::vector<std::string>& allowed,
                          std::string& value) {
    if (!d.contains(key)) return;
    r.string(d[key], child(p, key), value);
    if (!d[key].is_string() || std::find(allowed.begin(), allowed.end(), value) != allowed.end())
      return;
    std::string list;
    for (const auto& a : allowed)
      list += (list.empty() ? "" : ", ") + a;
    std::string message = fmt::format("expected one of {}, got {}", list, shown(d[key]));
    const std::string suggestion = closest_match(value, allowed);
    if (!suggestion.empty()) message += fmt::format("; did you mean \"{}\"?", suggestion);
    r.error(child(p, key), message);
  };
  out.reduce = "last";
  one_of("reduce", reductions, out.reduce);
  if (!d.contains("column") && !(events && out.reduce == "count"))
    r.error(p, "expected \"column\"");
  one_of("column", columns, out.column);
  if (events) one_of("kind", {"collision", "contact"}, out.kind);
  if (d.contains("body")) {
    r.string(d["body"], child(p, "body"), out.body);
  } else if (!events) {
    r.error(p, "expected \"body\": the name of a body that moves");
  }
  if (!out.body.empty() && scene.contains("bodies") && scene["bodies"].is_array()) {
    const json* found = nullptr;
    std::vector<std::string> names;
    for (const json& b : scene["bodies"]) {
      if (!b.is_object() || !b.contains("name") || !b["name"].is_string()) continue;
      names.push_back(b["name"].get<std::string>());
      if (names.back() == out.body) found = &b;
    }
    if (found == nullptr) {
      std::string message = fmt::format("the scene has no body named \"{}\"", out.body);
      const std::string suggestion = closest_match(out.body, names);
      if (!suggestion.empty()) message += fmt::format("; did you mean \"{}\"?", suggestion);
      r.error(child(p, "body"), message);
    } else if (!events && found->contains("fixed") && found->at("fixed") == json(true)) {
      r.error(child(p, "body"),
              fmt::format("\"{}\" is fixed: trajectory.csv has no rows of it", out.body));
    }
  }
  double t = 0.0;
  if (d.contains("from") && r.number(d["from"], child(p, "from"), t)) out.from = t;
  if (d.contains("to") && r.number(d["to"], child(p, "to"), t)) out.to = t;
  if (out.from && out.to && *out.to < *out.from)
    r.error(child(p, "to"), fmt::format("expected a time >= \"from\" ({})", *out.from));
}

void read_command(Reader& r, const json& c, const std::string& path, SweepCommand& out) {
  if (!r.is_object(c, path)) return;
  r.check_keys(c, path, {"simulate", "render"});
  if (c.size() != 1) {
    r.error(path, "expected exactly one of \"simulate\" and \"render\"");
    return;
  }
  out.render = c.contains("render");
  const std::string p = child(path, out.render ? "render" : "simulate");
  const json& o = c[out.render ? "render" : "simulate"];
  if (!r.is_object(o, p)) return;
  if (out.render)
    r.check_keys(o, p, {"accuracy", "duration", "fps", "size", "format", "crf"});
  else
    r.check_keys(o, p, {"accuracy", "duration", "fps", "outputs"});
  if (o.contains("accuracy")) {
    std::string preset;
    r.string(o["accuracy"], child(p, "accuracy"), preset);
    if (o["accuracy"].is_string() && preset != "draft" && preset != "normal" && preset != "precise")
      r.error(child(p, "accuracy"),
              fmt::format("expected draft, normal or precise, got {}", shown(o["accuracy"])));
    else if (!preset.empty())
      out.preset = preset;
  }
  double x = 0.0;
  if (o.contains("duration")) {
    r.positive(o["duration"], child(p, "duration"), x, "s");
    if (x > 0.0) out.duration = x;
  }
  if (o.contains("fps")) {
    x = 0.0;
    r.ranged(o["fps"], child(p, "fps"), x, 0.0, true, 1000.0, false, "a number in (0, 1000]");
    if (x > 0.0) out.fps = x;
  }
  if (o.contains("outputs")) {
    const json& list = o["outputs"];
    if (!list.is_array())
      r.error(child(p, "outputs"),
              "expected an array such as [\"trajectory\", \"events\", \"stats\"]");
    for (std::size_t i = 0; list.is_array() && i < list.size(); ++i) {
      std::string name;
      r.string(list[i], child(child(p, "outputs"), i), name);
      if (name == "trajectory" || name == "events" || name == "stats")
        out.outputs.push_back(name);
      else if (list[i].is_string())
        r.error(child(child(p, "outputs"), i),
                fmt::format("expected trajectory, events or stats, got {}", shown(list[i])));
    }
  }
  if (o.contains("size")) {
    r.string(o["size"], child(p, "size"), out.size);
    int w = 0, h = 0;
    char tail = 0;
    if (o["size"].is_string() && (std::sscanf(out.size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 ||
                                  w < 16 || h < 16 || w > 8192 || h > 8192))
      r.error(child(p, "size"),
              fmt::format("expected \"WxH\" with 16..8192 pixels each, got {}", shown(o["size"])));
  }
  if (o.contains("format")) {
    r.string(o["format"], child(p, "format"), out.format);
    if (o["format"].is_string() && out.format != "mp4" && out.format != "png")
      r.error(child(p, "format"), fmt::format("expected mp4 or png, got {}", shown(o["format"])));
  }
  if (o.contains("crf")) {
    std::size_t crf = 18;
    r.count(o["crf"], child(p, "crf"), crf, 0, 51, "x264's constant rate factor");
    out.crf = static_cast<int>(crf);
  }
}

// Every expression parsed with the names it may use: syntax errors and unknown names come out
// at load, with their JSON path.
void check_expressions(Reader& r, const SweepSpec& spec) {
  std::vector<std::pair<std::string, double>> variables;
  for (const SweepAxis& axis : spec.axes) {
    if (axis.numeric() && !axis.values.empty())
      variables.emplace_back(axis.name, axis.values[0].get<double>());
  }
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    for (const auto& [pointer, expression] : spec.axes[a].set) {
      try {
        expression_uses(expression, variables);
      } catch (const ExpressionError& e) {
        r.error(child(child(child(child("", "axes"), a), "set"), pointer), e.what());
      }
    }
  }
  for (std::size_t m = 0; m < spec.measures.size(); ++m) {
    const SweepMeasure& measure = spec.measures[m];
    if (measure.source == SweepMeasure::Source::kExpression) {
      try {
        expression_uses(measure.expression, variables);
      } catch (const ExpressionError& e) {
        r.error(child(child(child("", "measures"), m), "expression"), e.what());
      }
    }
    variables.emplace_back(measure.name, 1.0);
  }
}

}  // namespace

bool SweepAxis::numeric() const {
  return std::all_of(values.begin(), values.end(), [](const json& v) { return v.is_number(); });
}

std::size_t SweepSpec::task_count() const {
  std::size_t n = 1;
  for (const SweepAxis& axis : axes)
    n *= axis.values.size();
  return n;
}

std::vector<std::size_t> SweepSpec::coordinates(std::size_t task) const {
  std::vector<std::size_t> index(axes.size(), 0);
  for (std::size_t a = axes.size(); a-- > 0;) {
    index[a] = task % axes[a].values.size();
    task /= axes[a].values.size();
  }
  return index;
}

std::string SweepSpec::describe(std::size_t task) const {
  const std::vector<std::size_t> index = coordinates(task);
  std::string text;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (!text.empty()) text += ' ';
    text += axes[a].name + "=" + axes[a].values[index[a]].dump();
  }
  return text;
}

std::vector<std::pair<std::string, double>> task_variables(const SweepSpec& spec,
                                                           std::size_t task) {
  const std::vector<std::size_t> index = spec.coordinates(task);
  std::vector<std::pair<std::string, double>> variables;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (spec.axes[a].numeric())
      variables.emplace_back(spec.axes[a].name, spec.axes[a].values[index[a]].get<double>());
  }
  return variables;
}

json task_scene(const SweepSpec& spec, std::size_t task) {
  json scene = spec.scene;
  for (const auto& [pointer, value] : spec.set)
    scene[json::json_pointer(pointer)] = value;
  const std::vector<std::size_t> index = spec.coordinates(task);
  const auto variables = task_variables(spec, task);
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const SweepAxis& axis = spec.axes[a];
    if (!axis.pointer.empty()) scene[json::json_pointer(axis.pointer)] = axis.values[index[a]];
    for (const auto& [pointer, expression] : axis.set) {
      scene[json::json_pointer(pointer)] = number_value(evaluate_expression(expression, variables));
    }
  }
  return scene;
}

SweepSpecLoad load_sweep_spec(const std::string& path) {
  SweepSpecLoad load;
  SweepSpec& spec = load.spec;
  spec.file = path;
  Reader r(path, load.errors);
  bool readable = false;
  const std::string text = read_file(path, readable);
  if (!readable) {
    load.errors.push_back(
        {path, "", "cannot read the sweep spec (missing, a folder or unreadable)"});
    return load;
  }
  const std::optional<json> parsed = scene_json::parse_json_text(text, path, load.errors);
  if (!parsed || !r.is_object(*parsed, "")) return load;
  const json& root = *parsed;
  r.check_keys(root, "", {"version", "name", "scene", "set", "axes", "command", "measures"});
  std::size_t version = 0;
  if (!root.contains("version"))
    r.error("", "expected \"version\": 1");
  else
    r.count(root["version"], "/version", version, 1, 1, "the sweep format's version");
  spec.name = std::filesystem::path(path).stem().string();
  if (root.contains("name")) r.string(root["name"], "/name", spec.name);

  // The scene, relative to the spec's folder.
  std::string scene_text;
  if (!root.contains("scene")) {
    r.error("", "expected \"scene\": the scene file, relative to this spec's folder");
  } else if (root["scene"].is_string()) {
    const std::filesystem::path given = root["scene"].get<std::string>();
    spec.scene_path =
        (given.is_absolute() ? given : std::filesystem::path(path).parent_path() / given)
            .lexically_normal()
            .string();
    bool ok = false;
    scene_text = read_file(spec.scene_path, ok);
    if (!ok) {
      r.error("/scene", fmt::format("cannot read the scene file \"{}\"", spec.scene_path));
    } else {
      std::vector<SceneError> scene_errors;
      const std::optional<json> scene =
          scene_json::parse_json_text(scene_text, spec.scene_path, scene_errors);
      if (scene) spec.scene = *scene;
      for (SceneError& e : scene_errors)
        load.errors.push_back(std::move(e));
    }
  } else {
    r.error("/scene", "expected a string (the scene file), got " + shown(root["scene"]));
  }
  const bool have_scene = spec.scene.is_object();

  if (root.contains("set") && r.is_object(root["set"], "/set")) {
    for (const auto& [pointer, value] : root["set"].items()) {
      if (have_scene) check_pointer(r, spec.scene, pointer, child("/set", pointer));
      spec.set.emplace_back(pointer, value);
    }
  }

  std::set<std::string> taken;
  std::set<std::string> targets;  // pointers set by the axes: each by one only
  if (!root.contains("axes") || !root["axes"].is_array() || root["axes"].empty()) {
    r.error("/axes", "expected an array of at least one axis");
  } else {
    const json& axes = root["axes"];
    for (std::size_t i = 0; i < axes.size(); ++i) {
      const std::string p = child("/axes", i);
      const json& a = axes[i];
      if (!r.is_object(a, p)) continue;
      r.check_keys(a, p, {"name", "values", "range", "seeds", "pointer", "set"});
      SweepAxis axis;
      if (a.contains("name"))
        check_name(r, a["name"], child(p, "name"), axis.name, taken);
      else
        r.error(p, "expected \"name\"");
      read_axis_values(r, a, p, axis);
      const auto target = [&](const std::string& pointer, const std::string& at) {
        if (have_scene) check_pointer(r, spec.scene, pointer, at);
        if (!targets.insert(pointer).second)
          r.error(at, fmt::format("\"{}\" is set by another axis too", pointer));
      };
      if (a.contains("pointer")) {
        r.string(a["pointer"], child(p, "pointer"), axis.pointer);
        if (a["pointer"].is_string()) target(axis.pointer, child(p, "pointer"));
      }
      if (a.contains("set") && r.is_object(a["set"], child(p, "set"))) {
        for (const auto& [pointer, expression] : a["set"].items()) {
          const std::string at = child(child(p, "set"), pointer);
          if (!expression.is_string()) {
            r.error(at,
                    "expected an expression (a string such as \"9.81 * sin(angle * pi / "
                    "180)\"), got " +
                        shown(expression));
            continue;
          }
          target(pointer, at);
          axis.set.emplace_back(pointer, expression.get<std::string>());
        }
      }
      if (!a.contains("pointer") && !a.contains("set"))
        r.error(p,
                "expected \"pointer\" (where the value goes) or \"set\" (keys set from "
                "expressions of it), or both");
      if (!axis.set.empty() && !axis.numeric() && !axis.values.empty())
        r.error(child(p, "values"), "expected numbers: expressions use this axis's values");
      spec.axes.push_back(std::move(axis));
    }
  }
  // Other axes' expressions may use a numeric axis only.
  std::size_t tasks = 1;
  for (const SweepAxis& axis : spec.axes) {
    tasks = axis.values.empty() ? 0 : std::min(kMostTasks + 1, tasks * axis.values.size());
  }
  if (tasks > kMostTasks) r.error("/axes", fmt::format("expected at most {} tasks", kMostTasks));

  if (!root.contains("command"))
    r.error("", "expected \"command\": {\"simulate\": {...}} or {\"render\": {...}}");
  else
    read_command(r, root["command"], "/command", spec.command);

  if (root.contains("measures")) {
    const json& measures = root["measures"];
    if (!measures.is_array()) r.error("/measures", "expected an array of measures");
    for (std::size_t i = 0; measures.is_array() && i < measures.size(); ++i) {
      SweepMeasure measure;
      read_measure(r, measures[i], child("/measures", i), spec.scene, measure, taken);
      if (spec.command.render && measure.source != SweepMeasure::Source::kExpression &&
          measures[i].is_object())
        r.error(child("/measures", i),
                "a render task writes no telemetry: its measures can only "
                "be expressions (use a simulate sweep for the numbers)");
      spec.measures.push_back(std::move(measure));
    }
  }
  if (!load.errors.empty()) return load;
  check_expressions(r, spec);
  if (!load.errors.empty()) return load;

  // The first and last tasks' scenes against the scene format: a value out of range at either
  // end of an axis is found now, not in task 63 of 64.
  for (const std::size_t task : {std::size_t{0}, spec.task_count() - 1}) {
    try {
      const SceneLoad scene = parse_scene(task_scene(spec, task).dump(), spec.scene_path);
      for (const SceneError& e : scene.errors) {
        load.errors.push_back({path, e.path,
                               fmt::format("task {} ({}) makes a scene that is not valid: {}", task,
                                           spec.describe(task), e.message)});
      }
    } catch (const ExpressionError& e) {
      load.errors.push_back(
          {path, "/axes", fmt::format("task {} ({}): {}", task, spec.describe(task), e.what())});
    }
    if (!load.errors.empty() || spec.task_count() == 1) break;
  }
  Fnv1a hash;
  hash.add(text);
  hash.add(scene_text);
  spec.hash = hash.value();
  return load;
}

}  // namespace rugosim::app
