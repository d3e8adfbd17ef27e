// Reading a scene file (INTERFACE.md, "Scene file"; docs/scene-format.md): JSON with // and
// /* */ comments, every key checked. Validation does not stop at the first problem: it
// reports every one it finds, each with the file, the JSON path and what was expected, so a
// user fixes a scene in one pass. Geometric checks (a boundary crossing itself, bodies
// crossing at t = 0) need the bodies built: scene_world.h does them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

namespace rugosim {

struct SceneLoad {
  Scene scene;                     // complete only when errors is empty
  std::vector<SceneError> errors;  // every problem found, in the order of the file
  bool ok() const { return errors.empty(); }
};

// Reads and validates the file at `path`. A missing file, a directory or an unreadable file
// gives one error naming it.
SceneLoad load_scene_file(const std::string& path);

// Parses and validates JSON text; `file` names it in the errors.
SceneLoad parse_scene(std::string_view text, const std::string& file);

// The closest of `candidates` to `word` by edit distance, when close enough to be a likely
// typo (at most a third of the word's length, rounded up, and at least 1 edit); empty
// otherwise.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

// The index of the body called `name`, if any.
std::optional<std::size_t> find_body(const Scene& scene, const std::string& name);
// "no body named "x" (did you mean "y"?)": for a name that find_body does not find.
std::string unknown_body_message(const Scene& scene, const std::string& name);

}  // namespace rugosim
