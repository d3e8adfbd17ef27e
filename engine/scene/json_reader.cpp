#include "engine/scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rugosim::scene_json {
namespace {

// RFC 6901: "~" and "/" in a key become "~0" and "~1".
std::string pointer_token(std::string_view key) {
  std::string out;
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

// 1-based line and column of byte `offset` in `text`.
std::pair<int, int> line_column(std::string_view text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}
}  // namespace

std::string type_name(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::binary:
      return "binary data";
    case json::value_t::discarded:
      return "nothing";
    default:
      return "a number";
  }
}

// A value as the user wrote it, shortened, for "got ..." in messages.
std::string shown(const json& v) {
  if (v.is_object()) return type_name(v);
  if (v.is_array()) {
    // A short array of plain values is shown as written, e.g. [1, 0].
    const bool plain = v.size() <= 4 && std::none_of(v.begin(), v.end(), [](const json& e) {
                         return e.is_structured();
                       });
    if (!plain) return "an array of " + std::to_string(v.size());
  }
  std::string text = v.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

std::string child(const std::string& path, std::string_view key) {
  return path + "/" + pointer_token(key);
}

std::string child(const std::string& path, std::size_t index) {
  return path + "/" + std::to_string(index);
}

// Bytes a terminal would not show (control characters, invalid UTF-8) as \xNN.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    }
  }
  return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The scene loader's JSON reading, shared with the sweep specs (render/app/sweep_spec.h).
std::optional<json> parse_json_text(std::string_view text, const std::string& file,
                                    std::vector<SceneError>& errors) {
  json root;
  try {
    root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/true,
                       /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ...";
    // keep what follows the position, which says what was expected.
    std::string what = e.what();
    const std::size_t colon = what.find(": ", what.find("parse error"));
    const std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
    const auto [line, column] = line_column(text, e.byte == 0 ? 0 : e.byte - 1);
    errors.push_back({file, "", "invalid JSON: " + printable(reason), line, column});
    return std::nullopt;
  } catch (const json::exception& e) {
    // E.g. "number overflow parsing '1e999'": no position from the parser, so find the
    // quoted text in the file.
    std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    const std::string reason = bracket == std::string::npos ? what : what.substr(bracket + 2);
    int line = 1, column = 1;
    const std::size_t open = reason.find('\'');
    const std::size_t close = reason.rfind('\'');
    if (open != std::string::npos && close > open) {
      const std::size_t at = text.find(reason.substr(open + 1, close - open - 1));
      if (at != std::string_view::npos) std::tie(line, column) = line_column(text, at);
    }
    errors.push_back({file, "", "invalid JSON: " + reason, line, column});
    return std::nullopt;
  }
  return root;
}

}  // namespace rugosim::scene_json
