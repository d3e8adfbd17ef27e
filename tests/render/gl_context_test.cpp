// Off-screen OpenGL contexts (gl_context.h): both backends give a 4.5 core context on Mesa's
// llvmpipe and the same pixels for the same drawing.
#include "render/gl/gl_context.h"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

// A triangle with a colour from a uniform, on a cleared background: shaders, buffers, vertex
// arrays and rasterisation, all through the context's function table.
std::vector<std::uint8_t> draw_triangle(GlBackend backend, int width, int height) {
  const std::unique_ptr<GlContext> context = GlContext::create(backend, width, height);
  const GlApi& gl = context->gl();
  const char* vertex_source = R"(#version 450 core
    layout(location = 0) in vec2 position;
    void main() { gl_Position = vec4(position, 0.0, 1.0); })";
  const char* fragment_source = R"(#version 450 core
    uniform vec4 colour;
    out vec4 fragment;
    void main() { fragment = colour; })";
  auto compile = [&](GLenum kind, const char* source) {
    const GLuint shader = gl.CreateShader(kind);
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return shader;
  };
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, compile(GL_VERTEX_SHADER, vertex_source));
  gl.AttachShader(program, compile(GL_FRAGMENT_SHADER, fragment_source));
  gl.LinkProgram(program);
  GLint linked = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
  EXPECT_EQ(linked, GL_TRUE);

  const float vertices[] = {-0.8f, -0.8f, 0.8f, -0.6f, -0.1f, 0.9f};
  GLuint vao = 0, vbo = 0;
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.GenBuffers(1, &vbo);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
  gl.BufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);

  gl.ClearColor(0.95f, 0.94f, 0.92f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.UseProgram(program);
  gl.Uniform4f(gl.GetUniformLocation(program, "colour"), 0.2f, 0.4f, 0.8f, 1.0f);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.Finish();
  EXPECT_EQ(gl.GetError(), static_cast<GLenum>(GL_NO_ERROR));
  return context->read_pixels();
}

TEST(GlContext, BothBackendsGiveACoreContextOnLlvmpipe) {
  for (const GlBackend backend : {GlBackend::kOsmesa, GlBackend::kEgl}) {
    const std::unique_ptr<GlContext> context = GlContext::create(backend, 64, 32);
    const std::string renderer = context->renderer();
    RecordProperty(std::string(gl_backend_name(backend)), renderer);
    EXPECT_NE(renderer.find("4.5 (Core Profile)"), std::string::npos) << renderer;
    EXPECT_NE(renderer.find("llvmpipe"), std::string::npos) << renderer;
    EXPECT_EQ(context->width(), 64);
    EXPECT_EQ(context->height(), 32);
  }
}

TEST(GlContext, BackendsDrawIdenticalPixels) {
  const int w = 97, h = 61;  // odd sizes: no row padding hides a stride bug
  const std::vector<std::uint8_t> osmesa = draw_triangle(GlBackend::kOsmesa, w, h);
  const std::vector<std::uint8_t> egl = draw_triangle(GlBackend::kEgl, w, h);
  ASSERT_EQ(osmesa.size(), static_cast<std::size_t>(w * h * 4));
  EXPECT_EQ(osmesa, egl);
  // Background at the top-left corner (rows run top down), the triangle's colour inside it
  // (its centroid in NDC is (-0.03, -0.17): pixel (47, 35)).
  auto pixel = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>((y * w + x) * 4);
    return std::vector<int>{osmesa[i], osmesa[i + 1], osmesa[i + 2], osmesa[i + 3]};
  };
  EXPECT_EQ(pixel(0, 0), (std::vector<int>{242, 240, 235, 255}));
  EXPECT_EQ(pixel(47, 35), (std::vector<int>{51, 102, 204, 255}));
}

TEST(GlContext, RejectsBadSizesAndNames) {
  EXPECT_THROW(GlContext::create(GlBackend::kOsmesa, 0, 10), std::invalid_argument);
  EXPECT_THROW(GlContext::create(GlBackend::kEgl, 10, 20000), std::invalid_argument);
  EXPECT_EQ(parse_gl_backend("osmesa"), GlBackend::kOsmesa);
  EXPECT_EQ(parse_gl_backend("egl"), GlBackend::kEgl);
  EXPECT_EQ(parse_gl_backend("glx"), std::nullopt);
}

}  // namespace
}  // namespace rugosim
