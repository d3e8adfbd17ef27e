#include "render/app/sweep_spec_parts.h"

#include <algorithm>
#include <cstdio>

#include <fmt/core.h>

#include "engine/scene/scene_loader.h"
#include "render/app/sweep_expression.h"

namespace rugosim::app::sweep_spec_parts {
namespace {

using nlohmann::json;
using scene_json::child;
using scene_json::Reader;
using scene_json::shown;

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
                                             "soft_rest_retries",
                                             "body_steps",
                                             "sim_time",
                                             "wall_time",
                                             "stalled_time"};

}  // namespace

void check_name(Reader& r, const json& v, const std::string& path, std::string& out,
                std::set<std::string>& taken) {
  r.string(v, path, out);
  if (out.empty() && v.is_string()) {
    r.error(path, "expected a name, got \"\"");
  } else if (!out.empty() && !valid_variable_name(out)) {
    r.error(path, fmt::format("expected a name of letters, digits and \"_\" that does not start "
                              "with a digit and is not a built-in function or constant, got {}",
                              shown(v)));
  } else if (!out.empty() && (out == "task" || !taken.insert(out).second)) {
    r.error(path, fmt::format("the name \"{}\" is taken (by \"task\", an axis or a measure)", out));
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
  if (c.size() != 1 || !(c.contains("simulate") || c.contains("render"))) {
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

}  // namespace rugosim::app::sweep_spec_parts
