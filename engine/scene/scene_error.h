// A problem found in a scene file, as a user can act on it: the file, the JSON path of the
// offending value (RFC 6901, e.g. /bodies/1/material/density), what was expected, and for
// syntax errors the line and column.
#pragma once

#include <string>
#include <vector>

namespace rugosim {

struct SceneError {
  std::string file;
  std::string path;  // JSON pointer; empty for the file as a whole
  std::string message;
  int line = 0;  // 1-based, 0 when unknown
  int column = 0;

  // "file:line:column: message" for syntax errors, "file: /path: message" otherwise.
  std::string describe() const;
};

// Thrown by the loader's callers that want an exception rather than a list.
class SceneErrors : public std::exception {
 public:
  explicit SceneErrors(std::vector<SceneError> errors);
  const char* what() const noexcept override { return text_.c_str(); }
  const std::vector<SceneError>& errors() const { return errors_; }

 private:
  std::vector<SceneError> errors_;
  std::string text_;
};

}  // namespace rugosim
