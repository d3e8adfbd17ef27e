// An OpenGL 4.5 core-profile context for off-screen rendering, with two backends on Mesa's
// software rasteriser (llvmpipe): OSMesa (the default) and EGL surfaceless. Either way the
// frame is drawn into a framebuffer object of the requested size that the context owns, so
// both backends read back the same pixels. A context is current on the thread that created it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl/gl_api.h"

namespace rugosim {

enum class GlBackend { kOsmesa, kEgl };

std::optional<GlBackend> parse_gl_backend(std::string_view name);  // "osmesa", "egl"
std::string_view gl_backend_name(GlBackend backend);

// A backend that cannot give a 4.5 core context here, with the reason.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class GlContext {
 public:
  // Throws GlUnavailable when the backend cannot start, std::invalid_argument for a size
  // outside 1..16384.
  static std::unique_ptr<GlContext> create(GlBackend backend, int width, int height);
  virtual ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context the thread's current one when another was made current since (a thread
  // may hold several contexts, e.g. one per backend); cheap when it already is. Throws
  // GlUnavailable when the backend refuses.
  void make_current();

  const GlApi& gl() const { return gl_; }
  GlBackend backend() const { return backend_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // E.g. "4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits), osmesa": what a
  // golden image was made with.
  std::string renderer() const;

  // The framebuffer object every frame ends in (RGBA8, width × height), which read_pixels
  // reads.
  GLuint framebuffer() const { return framebuffer_; }

  // The framebuffer as RGBA8, rows from the top of the image down.
  std::vector<std::uint8_t> read_pixels() const;

 protected:
  GlContext(GlBackend backend, int width, int height);
  virtual bool bind() = 0;  // the backend's MakeCurrent
  // Loads the functions and creates the framebuffer; called by the backends once current.
  void initialise(void* (*get_proc)(const char*));

 private:
  GlBackend backend_;
  int width_;
  int height_;
  GlApi gl_;
  GLuint framebuffer_ = 0;
  GLuint colour_ = 0;
};

}  // namespace rugosim
