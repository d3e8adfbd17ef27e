#include "render/app/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include <fmt/core.h>

#include "engine/core/hash.h"
#include "engine/scene/json_reader.h"
#include "engine/scene/scene_loader.h"
#include "render/app/atomic_file.h"
#include "render/app/sweep_expression.h"
#include "render/app/sweep_spec_parts.h"

namespace rugosim::app {
namespace {

using nlohmann::json;
using scene_json::child;
using scene_json::Reader;
using scene_json::shown;
using sweep_spec_parts::check_name;
using sweep_spec_parts::read_command;
using sweep_spec_parts::read_measure;

constexpr std::size_t kMostTasks = 1000000;
constexpr std::size_t kMostValues = 100000;

// A whole number as a JSON integer (so that a seed or a count may come from an axis or an
// expression, and 100 reads "100", not "100.0"); any other as a double.
json number_value(double x) {
  if (std::abs(x) < 9007199254740992.0 && x == std::floor(x)) return static_cast<std::int64_t>(x);
  return x;
}

// RFC 6901's tokens of a pointer that starts with "/": "~1" is "/", "~0" is "~".
std::vector<std::string> pointer_tokens(const std::string& text) {
  std::vector<std::string> tokens;
  for (std::size_t at = 1; at <= text.size();) {
    const std::size_t end = std::min(text.find('/', at), text.size());
    std::string token;
    for (std::size_t i = at; i < end; ++i) {
      if (text[i] == '~' && i + 1 < end) {
        token += text[i + 1] == '1' ? '/' : '~';
        ++i;
      } else {
        token += text[i];
      }
    }
    tokens.push_back(std::move(token));
    at = end + 1;
  }
  return tokens;
}

// An array index as RFC 6901 writes one ("0", or digits without a leading zero) below `size`.
bool array_index(const std::string& token, std::size_t size) {
  if (token.empty() || token.size() > 18 || (token.size() > 1 && token[0] == '0')) return false;
  if (!std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  return std::stoull(token) < size;
}

// A JSON pointer whose parent exists in the scene (the key itself may be new: a default the
// scene leaves out; an array index must exist). Walked token by token here: nlohmann's own
// lookups throw on an index too large to read or written with a leading zero.
void check_pointer(Reader& r, const json& scene, const std::string& text, const std::string& path) {
  try {
    json::json_pointer{text};
  } catch (const json::exception&) {
    r.error(path, fmt::format("expected a JSON pointer into the scene such as "
                              "\"/world/friction_gain\", got \"{}\"",
                              text));
    return;
  }
  if (text.empty()) {
    r.error(path,
            "expected a JSON pointer to a value inside the scene, got \"\" (the whole scene)");
    return;
  }
  const std::vector<std::string> tokens = pointer_tokens(text);
  const json* at = &scene;
  std::string walked;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    const bool last = i + 1 == tokens.size();
    if (at->is_array()) {
      if (!array_index(token, at->size())) {
        r.error(path, fmt::format("\"{}\" is an array of {} values: expected an index below {} "
                                  "(no leading zeros), got \"{}\"",
                                  walked.empty() ? "/" : walked, at->size(), at->size(), token));
        return;
      }
      if (!last) at = &(*at)[std::stoull(token)];
    } else if (at->is_object()) {
      const auto found = at->find(token);
      if (found == at->end() && !last) {
        r.error(path, fmt::format("the scene has nothing at \"{}\"", child(walked, token)));
        return;
      }
      if (!last) at = &*found;
    } else {
      r.error(path, fmt::format("\"{}\" is {}, not an object or an array", walked,
                                scene_json::type_name(*at)));
      return;
    }
    walked = child(walked, token);
  }
}

// Two changes to the scene that overlap: the same key, or one inside the other.
bool overlaps(const std::string& a, const std::string& b) {
  const auto inside = [](const std::string& outer, const std::string& inner) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
           inner[outer.size()] == '/';
  };
  return a == b || inside(a, b) || inside(b, a);
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
    for (const json& x : v)  // a whole number as an integer, as the docs promise
      axis.values.push_back(x.is_number_float() ? number_value(x.get<double>()) : x);
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
        const double steps = std::abs(to - from) / step;
        const double whole = std::round(steps);
        if (whole + 1.0 > double(kMostValues)) {
          r.error(child(rp, "step"), fmt::format("expected at most {} values", kMostValues));
        } else if (std::abs(steps - whole) > 1e-9 * std::max(1.0, steps)) {
          // "to" is a value of the axis, exactly as written: the step must reach it.
          r.error(child(rp, "step"),
                  fmt::format("expected a step that divides to − from ({}) into whole steps, "
                              "got {} ({} steps); use \"count\" for evenly spaced values",
                              to - from, step, steps));
        } else {
          count = static_cast<std::size_t>(whole) + 1;
        }
      }
    }
    if (ok && count == 1 && from != to) {
      r.error(child(rp, "count"),
              "expected a count of at least 2 from \"from\" to a different "
              "\"to\" (both ends are values of the axis)");
      return;
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
    if (count > 0 && first > std::numeric_limits<std::uint64_t>::max() - (count - 1)) {
      r.error(child(sp, "count"), "expected the seeds to stay below 2^64 (first + count − 1)");
      return;
    }
    for (std::size_t i = 0; i < count; ++i)
      axis.values.emplace_back(first + i);
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
  const std::optional<std::string> spec_text = read_whole_file(path);
  if (!spec_text) {
    load.errors.push_back(
        {path, "", "cannot read the sweep spec (missing, a folder or unreadable)"});
    return load;
  }
  const std::string& text = *spec_text;
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
    std::optional<std::string> read = read_whole_file(spec.scene_path);
    if (!read) {
      r.error("/scene", fmt::format("cannot read the scene file \"{}\"", spec.scene_path));
    } else {
      scene_text = std::move(*read);
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

  // Every change to the scene, to find two that overlap (the same key, or one inside the
  // other): which applies would depend on their order.
  std::vector<std::string> targets;
  const auto target = [&](const std::string& pointer, const std::string& at) {
    if (have_scene) check_pointer(r, spec.scene, pointer, at);
    for (const std::string& other : targets) {
      if (pointer == other) {
        r.error(at, fmt::format("\"{}\" is set elsewhere in the spec too", pointer));
        break;
      }
      if (overlaps(pointer, other)) {
        r.error(at, fmt::format("\"{}\" overlaps \"{}\", which the spec sets too", pointer, other));
        break;
      }
    }
    targets.push_back(pointer);
  };
  if (root.contains("set") && r.is_object(root["set"], "/set")) {
    for (const auto& [pointer, value] : root["set"].items()) {
      target(pointer, child("/set", pointer));
      spec.set.emplace_back(pointer, value);
    }
  }

  std::set<std::string> taken;
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
    } catch (const std::exception& e) {  // an expression without a value, a JSON error
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
