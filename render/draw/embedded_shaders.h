// The GLSL sources of shaders/, compiled into the binary (cmake/EmbedShaders.cmake).
#pragma once

#include <string_view>

namespace rugosim {

// The source of shaders/<name> (e.g. "outline.vert"), empty when there is no such file. The
// sources carry no #version line: ShaderProgram adds it with any #defines.
std::string_view embedded_shader(std::string_view name);

}  // namespace rugosim
