#include "engine/scene/scene_error.h"

#include <utility>

namespace rugosim {

std::string SceneError::describe() const {
  // append rather than operator+: GCC 12 warns falsely (-Wrestrict) on "literal" + string.
  std::string out = file;
  if (line > 0) {
    out.append(":").append(std::to_string(line)).append(":").append(std::to_string(column));
  }
  out.append(": ");
  if (!path.empty()) out.append(path).append(": ");
  out.append(message);
  return out;
}

SceneErrors::SceneErrors(std::vector<SceneError> errors) : errors_(std::move(errors)) {
  for (const SceneError& e : errors_) {
    if (!text_.empty()) text_ += '\n';
    text_ += e.describe();
  }
}

}  // namespace rugosim
