// Reading scene JSON with errors that name the JSON path and say what was expected
// (scene_loader.h): the helpers every part of the loader shares, and the sweep specs
// (render/app/sweep_spec.h), which follow the same conventions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/types.h"
#include "engine/scene/scene_error.h"
#include "engine/scene/scene_loader.h"

namespace rugosim::scene_json {

using nlohmann::json;

// "null", "a boolean", "a string", "an array", "an object", "a number", ...
std::string type_name(const json& v);
// A value as the user wrote it, shortened, for "got ..." in messages.
std::string shown(const json& v);
// path + "/" + key, the key escaped as RFC 6901 says ("~" → "~0", "/" → "~1").
std::string child(const std::string& path, std::string_view key);
std::string child(const std::string& path, std::size_t index);
// Bytes a terminal would not show (control characters, invalid UTF-8) as \xNN.
std::string printable(const std::string& text);
// Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b);

// JSON text with // and /* */ comments parsed; nullopt after adding the syntax error to `errors`
// (`file`, the line and column, what the parser expected).
std::optional<nlohmann::json> parse_json_text(std::string_view text, const std::string& file,
                                              std::vector<SceneError>& errors);

// Checks values against what the format expects, and records every problem as a SceneError
// with the file, the JSON path and the expectation.
class Reader {
 public:
  Reader(std::string file, std::vector<SceneError>& errors)
      : file_(std::move(file)), errors_(errors) {}

  void error(const std::string& path, std::string message) {
    errors_.push_back({file_, path.empty() ? "/" : path, std::move(message), 0, 0});
  }

  // Reports keys of `object` not in `allowed`, with a suggestion when one is close.
  void check_keys(const json& object, const std::string& path,
                  const std::vector<std::string>& allowed) {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string message = "unknown key \"" + key + "\"";
      const std::string suggestion = closest_match(key, allowed);
      if (!suggestion.empty()) message += "; did you mean \"" + suggestion + "\"?";
      error(child(path, key), message);
    }
  }

  bool is_object(const json& v, const std::string& path) {
    if (v.is_object()) return true;
    error(path, "expected an object, got " + shown(v));
    return false;
  }

  bool number(const json& v, const std::string& path, double& out) {
    if (!v.is_number()) {
      error(path, "expected a number, got " + shown(v));
      return false;
    }
    const double x = v.get<double>();
    if (!std::isfinite(x)) {
      error(path, "expected a finite number, got " + shown(v));
      return false;
    }
    out = x;
    return true;
  }

  // A finite number in [lo, hi] (either end may be open); `what` names the unit or range.
  void ranged(const json& v, const std::string& path, double& out, double lo, bool lo_open,
              double hi, bool hi_open, const std::string& expectation) {
    double x = 0.0;
    if (!number(v, path, x)) return;
    const bool above = lo_open ? x > lo : x >= lo;
    const bool below = hi_open ? x < hi : x <= hi;
    if (!(above && below)) {
      error(path, "expected " + expectation + ", got " + shown(v));
      return;
    }
    out = x;
  }

  void positive(const json& v, const std::string& path, double& out, const std::string& unit) {
    ranged(v, path, out, 0.0, true, std::numeric_limits<double>::infinity(), true,
           "a number > 0" + (unit.empty() ? std::string() : " (" + unit + ")"));
  }

  void vec2(const json& v, const std::string& path, Vec2& out) {
    if (!v.is_array() || v.size() != 2) {
      error(path, "expected an array of 2 numbers [x, y], got " + shown(v));
      return;
    }
    double x = 0.0, y = 0.0;
    const bool ok_x = number(v[0], child(path, 0), x);
    const bool ok_y = number(v[1], child(path, 1), y);
    if (ok_x && ok_y) out = Vec2(x, y);
  }

  void boolean(const json& v, const std::string& path, bool& out) {
    if (!v.is_boolean()) {
      error(path, "expected true or false, got " + shown(v));
      return;
    }
    out = v.get<bool>();
  }

  void string(const json& v, const std::string& path, std::string& out) {
    if (!v.is_string()) {
      error(path, "expected a string, got " + shown(v));
      return;
    }
    out = v.get<std::string>();
  }

  void count(const json& v, const std::string& path, std::size_t& out, std::size_t lo,
             std::size_t hi, const std::string& what) {
    const std::string expectation =
        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (" + what + ")";
    if (!v.is_number_integer()) {
      error(path, "expected " + expectation + ", got " + shown(v));
      return;
    }
    if (v.is_number_unsigned() || v.get<std::int64_t>() >= 0) {
      const auto n = v.get<std::uint64_t>();
      if (n >= lo && n <= hi) {
        out = static_cast<std::size_t>(n);
        return;
      }
    }
    error(path, "expected " + expectation + ", got " + shown(v));
  }

  void seed(const json& v, const std::string& path, std::uint64_t& out) {
    if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0)) {
      error(path, "expected an integer in [0, 2^64 - 1], got " + shown(v));
      return;
    }
    out = v.get<std::uint64_t>();
  }

 private:
  std::string file_;
  std::vector<SceneError>& errors_;
};

}  // namespace rugosim::scene_json
