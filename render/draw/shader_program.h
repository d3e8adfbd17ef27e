// A linked GLSL program made from embedded shaders (shaders/), with a #version line and
// #defines put in front of each source. Compile and link errors name the shader file and carry
// the driver's log.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "render/gl/gl_api.h"

namespace rugosim {

class ShaderProgram {
 public:
  // Throws std::runtime_error for a missing shader or a compile/link error.
  ShaderProgram(const GlApi& gl, std::string_view vertex_file, std::string_view fragment_file,
                const std::vector<std::string>& defines = {});
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  void use() const { gl_.UseProgram(program_); }
  // -1 when the program has no such active uniform (GL ignores setting it).
  GLint uniform(const char* name) const { return gl_.GetUniformLocation(program_, name); }

 private:
  const GlApi& gl_;
  GLuint program_ = 0;
};

}  // namespace rugosim
