#include "render/gl/gl_context.h"

#include <cstring>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>

extern "C" void __lsan_disable() __attribute__((weak));

namespace rugosim {
namespace {

constexpr int kMaxSide = 16384;

// The context this thread last made current (through GlContext), so that switching between
// contexts costs a MakeCurrent only when it is needed.
thread_local const GlContext* t_current = nullptr;

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext(int width, int height) : GlContext(GlBackend::kOsmesa, width, height) {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) {
      throw GlUnavailable("OSMesa: no OpenGL 4.5 core context (is Mesa's libOSMesa installed?)");
    }
    if (!bind()) {
      OSMesaDestroyContext(context_);
      throw GlUnavailable("OSMesa: cannot make the context current");
    }
    initialise(
        [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

 protected:
  // OSMesa needs a buffer to be current; frames go to the framebuffer object instead, so a
  // single pixel does.
  bool bind() override { return OSMesaMakeCurrent(context_, &dummy_, GL_UNSIGNED_BYTE, 1, 1) != 0; }

 private:
  OSMesaContext context_ = nullptr;
  std::uint32_t dummy_ = 0;
};

class EglContext final : public GlContext {
 public:
  EglContext(int width, int height) : GlContext(GlBackend::kEgl, width, height) {
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display == nullptr) {
      throw GlUnavailable("EGL: eglGetPlatformDisplayEXT is missing (EGL_EXT_platform_base)");
    }
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
      throw GlUnavailable("EGL: no surfaceless Mesa display (EGL_MESA_platform_surfaceless)");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      eglTerminate(display_);
      throw GlUnavailable("EGL: desktop OpenGL is not available");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): the
    // frame goes to a framebuffer object.
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT || !bind()) {
      if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
      eglTerminate(display_);
      throw GlUnavailable("EGL: no OpenGL 4.5 core context without a surface");
    }
    initialise([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

 protected:
  bool bind() override {
    return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE;
  }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::optional<GlBackend> parse_gl_backend(std::string_view name) {
  if (name == "osmesa") return GlBackend::kOsmesa;
  if (name == "egl") return GlBackend::kEgl;
  return std::nullopt;
}

std::string_view gl_backend_name(GlBackend backend) {
  return backend == GlBackend::kOsmesa ? "osmesa" : "egl";
}

std::unique_ptr<GlContext> GlContext::create(GlBackend backend, int width, int height) {
  // Under LeakSanitizer (the asan preset): Mesa's llvmpipe keeps allocations made from its
  // JIT-compiled code for the life of the process, which LeakSanitizer can neither attribute
  // (an unknown module) nor suppress by name. The thread that draws is the thread that creates
  // the context, so leak checks are off for it; AddressSanitizer's other checks stay on.
  // Without sanitizers the weak symbol is null and nothing happens.
  if (&__lsan_disable != nullptr) __lsan_disable();
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    throw std::invalid_argument("frame size must be 1..16384 pixels a side, got " +
                                std::to_string(width) + "x" + std::to_string(height));
  }
  if (backend == GlBackend::kOsmesa) return std::make_unique<OsmesaContext>(width, height);
  return std::make_unique<EglContext>(width, height);
}

GlContext::GlContext(GlBackend backend, int width, int height)
    : backend_(backend), width_(width), height_(height) {}

GlContext::~GlContext() {
  if (t_current == this) t_current = nullptr;
}

void GlContext::make_current() {
  if (t_current == this) return;
  if (!bind()) {
    throw GlUnavailable(std::string(gl_backend_name(backend_)) +
                        ": cannot make the context current");
  }
  t_current = this;
}

void GlContext::initialise(void* (*get_proc)(const char*)) {
  t_current = this;
  try {
    gl_.load(get_proc);
  } catch (const std::runtime_error& e) {
    throw GlUnavailable(std::string(gl_backend_name(backend_)) + ": " + e.what());
  }
  gl_.GenFramebuffers(1, &framebuffer_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.GenRenderbuffers(1, &colour_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, colour_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw GlUnavailable(std::string(gl_backend_name(backend_)) +
                        ": the off-screen framebuffer is incomplete");
  }
  gl_.Viewport(0, 0, width_, height_);
}

std::string GlContext::renderer() const {
  auto text = [&](GLenum name) {
    const GLubyte* s = gl_.GetString(name);
    return s != nullptr ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VERSION) + ", " + text(GL_RENDERER) + ", " +
         std::string(gl_backend_name(backend_));
}

std::vector<std::uint8_t> GlContext::read_pixels() const {
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  std::vector<std::uint8_t> bottom_up(w * h * 4);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  // OpenGL's rows start at the bottom; images start at the top.
  std::vector<std::uint8_t> top_down(bottom_up.size());
  for (std::size_t row = 0; row < h; ++row) {
    std::memcpy(&top_down[row * w * 4], &bottom_up[(h - 1 - row) * w * 4], w * 4);
  }
  return top_down;
}

}  // namespace rugosim
