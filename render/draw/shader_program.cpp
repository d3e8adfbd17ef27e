#include "render/draw/shader_program.h"

#include <stdexcept>

#include "render/draw/embedded_shaders.h"

namespace rugosim {
namespace {

GLuint compile(const GlApi& gl, GLenum kind, std::string_view file,
               const std::vector<std::string>& defines) {
  const std::string_view body = embedded_shader(file);
  if (body.empty()) {
    throw std::runtime_error(std::string("no embedded shader named ").append(file));
  }
  std::string source = "#version 450 core\n";
  for (const std::string& define : defines)
    source.append("#define ").append(define).append("\n");
  source.append("#line 1\n").append(body);
  const char* text = source.c_str();
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw std::runtime_error(std::string("shaders/").append(file).append(": ").append(log));
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const GlApi& gl, std::string_view vertex_file,
                             std::string_view fragment_file,
                             const std::vector<std::string>& defines)
    : gl_(gl) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_file, defines);
  GLuint fragment = 0;
  try {
    fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_file, defines);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  program_ = gl.CreateProgram();
  gl.AttachShader(program_, vertex);
  gl.AttachShader(program_, fragment);
  gl.LinkProgram(program_);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetProgramInfoLog(program_, sizeof log, nullptr, log);
    gl.DeleteProgram(program_);
    throw std::runtime_error(std::string("linking shaders/")
                                 .append(vertex_file)
                                 .append(" with ")
                                 .append(fragment_file)
                                 .append(": ")
                                 .append(log));
  }
}

ShaderProgram::~ShaderProgram() {
  gl_.DeleteProgram(program_);
}

}  // namespace rugosim
