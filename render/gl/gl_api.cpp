#include "render/gl/gl_api.h"

#include <stdexcept>

namespace rugosim {
namespace {

template <typename F>
void resolve(F& entry, const char* name, const std::function<void*(const char*)>& get) {
  void* address = get(name);
  if (address == nullptr) {
    throw std::runtime_error(std::string("OpenGL function ") + name +
                             " is not available from this backend");
  }
  // A data pointer to a function pointer: how every GetProcAddress hands out functions.
  entry = reinterpret_cast<F>(address);
}

}  // namespace

void GlApi::load(const std::function<void*(const char*)>& get) {
#define RUGOSIM_GL(name) resolve(name, "gl" #name, get)
  RUGOSIM_GL(GetString);
  RUGOSIM_GL(GetError);
  RUGOSIM_GL(Viewport);
  RUGOSIM_GL(ClearColor);
  RUGOSIM_GL(Clear);
  RUGOSIM_GL(Finish);
  RUGOSIM_GL(PixelStorei);
  RUGOSIM_GL(ReadPixels);
  RUGOSIM_GL(GenFramebuffers);
  RUGOSIM_GL(DeleteFramebuffers);
  RUGOSIM_GL(BindFramebuffer);
  RUGOSIM_GL(CheckFramebufferStatus);
  RUGOSIM_GL(GenRenderbuffers);
  RUGOSIM_GL(DeleteRenderbuffers);
  RUGOSIM_GL(BindRenderbuffer);
  RUGOSIM_GL(RenderbufferStorage);
  RUGOSIM_GL(FramebufferRenderbuffer);
  RUGOSIM_GL(CreateShader);
  RUGOSIM_GL(ShaderSource);
  RUGOSIM_GL(CompileShader);
  RUGOSIM_GL(GetShaderiv);
  RUGOSIM_GL(GetShaderInfoLog);
  RUGOSIM_GL(DeleteShader);
  RUGOSIM_GL(CreateProgram);
  RUGOSIM_GL(AttachShader);
  RUGOSIM_GL(LinkProgram);
  RUGOSIM_GL(GetProgramiv);
  RUGOSIM_GL(GetProgramInfoLog);
  RUGOSIM_GL(UseProgram);
  RUGOSIM_GL(DeleteProgram);
  RUGOSIM_GL(GetUniformLocation);
  RUGOSIM_GL(Uniform4f);
  RUGOSIM_GL(GenVertexArrays);
  RUGOSIM_GL(DeleteVertexArrays);
  RUGOSIM_GL(BindVertexArray);
  RUGOSIM_GL(GenBuffers);
  RUGOSIM_GL(DeleteBuffers);
  RUGOSIM_GL(BindBuffer);
  RUGOSIM_GL(BufferData);
  RUGOSIM_GL(EnableVertexAttribArray);
  RUGOSIM_GL(VertexAttribPointer);
  RUGOSIM_GL(DrawArrays);
  RUGOSIM_GL(DrawElements);
  RUGOSIM_GL(MultiDrawElements);
  RUGOSIM_GL(Scissor);
  RUGOSIM_GL(Enable);
  RUGOSIM_GL(Disable);
  RUGOSIM_GL(BlendFunc);
  RUGOSIM_GL(BlendFuncSeparate);
  RUGOSIM_GL(LogicOp);
  RUGOSIM_GL(DrawArraysInstanced);
  RUGOSIM_GL(BufferSubData);
  RUGOSIM_GL(Uniform1f);
  RUGOSIM_GL(Uniform2f);
  RUGOSIM_GL(Uniform1i);
  RUGOSIM_GL(Uniform1ui);
  RUGOSIM_GL(GenTextures);
  RUGOSIM_GL(DeleteTextures);
  RUGOSIM_GL(BindTexture);
  RUGOSIM_GL(ActiveTexture);
  RUGOSIM_GL(TexParameteri);
  RUGOSIM_GL(TexStorage2D);
  RUGOSIM_GL(TexStorage2DMultisample);
  RUGOSIM_GL(TexBuffer);
  RUGOSIM_GL(FramebufferTexture2D);
  RUGOSIM_GL(BlitFramebuffer);
  RUGOSIM_GL(RenderbufferStorageMultisample);
  RUGOSIM_GL(VertexAttribIPointer);
  RUGOSIM_GL(VertexAttribDivisor);
  RUGOSIM_GL(ClearBufferuiv);
  RUGOSIM_GL(ClearBufferfv);
  RUGOSIM_GL(GetIntegerv);
#undef RUGOSIM_GL
}

}  // namespace rugosim
