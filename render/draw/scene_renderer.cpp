#include "render/draw/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/geometry/tolerance_profile.h"
#include "render/draw/palette.h"
#include "render/draw/shader_program.h"

namespace rugosim {
namespace {

constexpr int kMsaaSamples = 4;
constexpr std::size_t kMaxBodies = 65535;  // body index + 1 must fit the 16-bit id target

struct FillVertex {
  float x, y;          // m, body frame
  std::uint32_t body;  // index
};

struct OutlineVertex {
  float x, y;          // m, body frame
  std::uint32_t body;  // index
  float miter_x, miter_y;
  float side;
  float lambda;  // λ / largest λ of the scene
};

// Unit outward normal of the edge a → b of a counter-clockwise outline.
Vec2 edge_normal(const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length = d.norm();
  return length > 0.0 ? Vec2(d.y() / length, -d.x() / length) : Vec2::Zero();
}

// The direction and length a vertex moves to keep both edges' offsets `1` away: the bisector of
// the two normals over the cosine of half the turn, capped at 2 so that spikes stay short.
Vec2 miter(const Vec2& before, const Vec2& at, const Vec2& after) {
  const Vec2 n1 = edge_normal(before, at);
  const Vec2 n2 = edge_normal(at, after);
  Vec2 sum = n1 + n2;
  const double length = sum.norm();
  if (!(length > 1e-12)) return n1.squaredNorm() > 0.0 ? n1 : n2;
  sum /= length;
  const double cosine = sum.dot(n1.squaredNorm() > 0.0 ? n1 : n2);
  return sum / std::max(cosine, 0.5);
}

void set_attribute(const GlApi& gl, GLuint index, GLint size, GLenum type, GLsizei stride,
                   std::size_t offset) {
  gl.EnableVertexAttribArray(index);
  const void* pointer = reinterpret_cast<const void*>(offset);
  if (type == GL_UNSIGNED_INT) {
    gl.VertexAttribIPointer(index, size, type, stride, pointer);
  } else {
    gl.VertexAttribPointer(index, size, type, GL_FALSE, stride, pointer);
  }
}

}  // namespace

std::optional<AntiAliasing> parse_anti_aliasing(std::string_view name) {
  if (name == "shader") return AntiAliasing::kShader;
  if (name == "msaa") return AntiAliasing::kMsaa;
  if (name == "none") return AntiAliasing::kNone;
  return std::nullopt;
}

std::string_view anti_aliasing_name(AntiAliasing aa) {
  switch (aa) {
    case AntiAliasing::kShader:
      return "shader";
    case AntiAliasing::kMsaa:
      return "msaa";
    case AntiAliasing::kNone:
      return "none";
  }
  return "?";
}

struct SceneRenderer::GpuState {
  explicit GpuState(const GlApi& gl, bool msaa)
      : fill(gl, "body_fill.vert", "body_fill.frag"),
        resolve(gl, "body_fill.vert", "body_resolve.frag",
                msaa ? std::vector<std::string>{"MSAA 1"} : std::vector<std::string>{}),
        outline(gl, "outline.vert", "outline.frag"),
        overlay(gl, "overlay.vert", "overlay.frag") {}

  ShaderProgram fill;
  ShaderProgram resolve;
  ShaderProgram outline;
  ShaderProgram overlay;
  GLuint fill_vao = 0, fill_vbo = 0;
  GLsizei fill_count = 0;
  GLuint outline_vao = 0, outline_vbo = 0;
  GLsizei outline_count = 0;
  GLuint bounds_vao = 0, bounds_vbo = 0;  // per body, its box in the body frame (2 triangles)
  GLsizei bounds_count = 0;
  GLuint overlay_vao = 0, overlay_vbo = 0;
  std::size_t overlay_capacity = 0;  // vertices the overlay buffer holds
  GLuint transform_buffer = 0, transform_texture = 0;
  GLuint palette_buffer = 0, palette_texture = 0;
  GLuint id_texture = 0, id_framebuffer = 0;
  GLuint msaa_colour = 0, msaa_framebuffer = 0;  // MSAA only
  std::vector<float> transforms;                 // 8 floats per body, refilled each frame
};

SceneRenderer::SceneRenderer(GlContext& context, std::vector<BodyLook> bodies,
                             const RenderSettings& settings)
    : context_(context),
      gl_(context.gl()),
      bodies_(std::move(bodies)),
      settings_(settings),
      overlay_builder_(settings.camera, settings.anti_aliasing == AntiAliasing::kShader ? 1.f : 0.f,
                       static_cast<float>(std::max(1.0, settings.camera.height_px / 720.0)), true) {
  if (settings_.camera.width_px != context.width() ||
      settings_.camera.height_px != context.height()) {
    throw std::invalid_argument("renderer: the camera's frame size differs from the context's");
  }
  if (bodies_.size() > kMaxBodies) {
    throw std::invalid_argument("renderer: at most 65535 bodies can be drawn");
  }
  settings_.detail.pixel_size = settings_.camera.pixel_size();
  context_.make_current();
  gpu_ = std::make_unique<GpuState>(gl_, settings_.anti_aliasing == AntiAliasing::kMsaa);
  for (const BodyLook& body : bodies_)
    fixed_.push_back(body.fixed);
  build_meshes();
  create_targets();
  if (gl_.GetError() != GL_NO_ERROR) {
    throw GlUnavailable("renderer: the GL context refused to set up the frame targets");
  }
}

SceneRenderer::~SceneRenderer() {
  try {
    context_.make_current();
  } catch (const GlUnavailable&) {
    return;  // the objects go with the context
  }
  GpuState& g = *gpu_;
  const GLuint arrays[] = {g.fill_vao, g.bounds_vao, g.outline_vao, g.overlay_vao};
  gl_.DeleteVertexArrays(4, arrays);
  const GLuint buffers[] = {g.fill_vbo,    g.bounds_vbo,       g.outline_vbo,
                            g.overlay_vbo, g.transform_buffer, g.palette_buffer};
  gl_.DeleteBuffers(6, buffers);
  const GLuint textures[] = {g.transform_texture, g.palette_texture, g.id_texture};
  gl_.DeleteTextures(3, textures);
  const GLuint framebuffers[] = {g.id_framebuffer, g.msaa_framebuffer};
  gl_.DeleteFramebuffers(2, framebuffers);
  gl_.DeleteRenderbuffers(1, &g.msaa_colour);
}

void SceneRenderer::build_meshes() {
  GpuState& g = *gpu_;
  double largest_lambda = 0.0;
  std::vector<ToleranceProfile> profiles;
  for (const BodyLook& body : bodies_) {
    profiles.push_back(ToleranceProfile(body.lambda));
    largest_lambda = std::max(largest_lambda, profiles.back().range().hi);
  }
  std::vector<FillVertex> fill;
  std::vector<FillVertex> bounds;
  std::vector<OutlineVertex> outline;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodyLook& body = bodies_[b];
    outlines_.push_back(make_detail_outline(body.curve, body.sigma, body.seed, settings_.detail));
    const std::vector<Vec2>& p = outlines_.back().points;
    const std::vector<double>& u = outlines_.back().param;
    const std::size_t n = p.size();
    Vec2 anchor = Vec2::Zero();
    Vec2 lo = p.front(), hi = p.front();
    for (const Vec2& q : p) {
      anchor += q;
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    anchor /= static_cast<double>(n);
    const auto body_index = static_cast<std::uint32_t>(b);
    // The box the resolve pass covers, a pixel wider for the rasteriser's rounding.
    const double pad = settings_.detail.pixel_size;
    const Vec2 corners[4] = {Vec2(lo.x() - pad, lo.y() - pad), Vec2(hi.x() + pad, lo.y() - pad),
                             Vec2(lo.x() - pad, hi.y() + pad), Vec2(hi.x() + pad, hi.y() + pad)};
    for (const int c : {0, 1, 2, 2, 1, 3}) {
      bounds.push_back(FillVertex{static_cast<float>(corners[c].x()),
                                  static_cast<float>(corners[c].y()), body_index});
    }
    auto fill_vertex = [&](const Vec2& q) {
      fill.push_back(FillVertex{static_cast<float>(q.x()), static_cast<float>(q.y()), body_index});
    };
    std::vector<OutlineVertex> ring;  // two per point: inside, outside
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& q = p[i];
      fill_vertex(anchor);
      fill_vertex(q);
      fill_vertex(p[(i + 1) % n]);
      const Vec2 m = miter(p[(i + n - 1) % n], q, p[(i + 1) % n]);
      const auto j = static_cast<std::size_t>(u[i]) % body.curve.size();
      const double lambda = profiles[b].at(j, u[i] - std::floor(u[i]));
      const float level = largest_lambda > 0.0 ? static_cast<float>(lambda / largest_lambda) : 0.f;
      for (const float side : {-1.f, 1.f}) {
        ring.push_back(OutlineVertex{static_cast<float>(q.x()), static_cast<float>(q.y()),
                                     body_index, static_cast<float>(m.x()),
                                     static_cast<float>(m.y()), side, level});
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = (i + 1) % n;
      for (const std::size_t v : {2 * i, 2 * i + 1, 2 * k, 2 * k, 2 * i + 1, 2 * k + 1}) {
        outline.push_back(ring[v]);
      }
    }
  }
  g.fill_count = static_cast<GLsizei>(fill.size());
  g.bounds_count = static_cast<GLsizei>(bounds.size());
  g.outline_count = static_cast<GLsizei>(outline.size());

  gl_.GenVertexArrays(1, &g.fill_vao);
  gl_.BindVertexArray(g.fill_vao);
  gl_.GenBuffers(1, &g.fill_vbo);
  gl_.BindBuffer(GL_ARRAY_BUFFER, g.fill_vbo);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(fill.size() * sizeof(FillVertex)),
                 fill.data(), GL_STATIC_DRAW);
  set_attribute(gl_, 0, 2, GL_FLOAT, sizeof(FillVertex), offsetof(FillVertex, x));
  set_attribute(gl_, 1, 1, GL_UNSIGNED_INT, sizeof(FillVertex), offsetof(FillVertex, body));

  gl_.GenVertexArrays(1, &g.bounds_vao);
  gl_.BindVertexArray(g.bounds_vao);
  gl_.GenBuffers(1, &g.bounds_vbo);
  gl_.BindBuffer(GL_ARRAY_BUFFER, g.bounds_vbo);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bounds.size() * sizeof(FillVertex)),
                 bounds.data(), GL_STATIC_DRAW);
  set_attribute(gl_, 0, 2, GL_FLOAT, sizeof(FillVertex), offsetof(FillVertex, x));
  set_attribute(gl_, 1, 1, GL_UNSIGNED_INT, sizeof(FillVertex), offsetof(FillVertex, body));

  gl_.GenVertexArrays(1, &g.outline_vao);
  gl_.BindVertexArray(g.outline_vao);
  gl_.GenBuffers(1, &g.outline_vbo);
  gl_.BindBuffer(GL_ARRAY_BUFFER, g.outline_vbo);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(outline.size() * sizeof(OutlineVertex)),
                 outline.data(), GL_STATIC_DRAW);
  constexpr GLsizei kStride = sizeof(OutlineVertex);
  set_attribute(gl_, 0, 2, GL_FLOAT, kStride, offsetof(OutlineVertex, x));
  set_attribute(gl_, 1, 1, GL_UNSIGNED_INT, kStride, offsetof(OutlineVertex, body));
  set_attribute(gl_, 2, 2, GL_FLOAT, kStride, offsetof(OutlineVertex, miter_x));
  set_attribute(gl_, 3, 1, GL_FLOAT, kStride, offsetof(OutlineVertex, side));
  set_attribute(gl_, 4, 1, GL_FLOAT, kStride, offsetof(OutlineVertex, lambda));

  gl_.GenVertexArrays(1, &g.overlay_vao);
  gl_.BindVertexArray(g.overlay_vao);
  gl_.GenBuffers(1, &g.overlay_vbo);
  gl_.BindBuffer(GL_ARRAY_BUFFER, g.overlay_vbo);
  constexpr GLsizei kOverlayStride = sizeof(OverlayVertex);
  set_attribute(gl_, 0, 2, GL_FLOAT, kOverlayStride, offsetof(OverlayVertex, x));
  set_attribute(gl_, 1, 2, GL_FLOAT, kOverlayStride, offsetof(OverlayVertex, along));
  set_attribute(gl_, 2, 4, GL_FLOAT, kOverlayStride, offsetof(OverlayVertex, r));
  set_attribute(gl_, 3, 2, GL_FLOAT, kOverlayStride, offsetof(OverlayVertex, half_width));

  gl_.BindVertexArray(0);

  // Per body: transform (2 texels, refilled each frame) and colours (fill, outline).
  g.transforms.assign(bodies_.size() * 8, 0.f);
  std::vector<float> palette;
  palette.reserve(bodies_.size() * 8);
  for (const BodyLook& body : bodies_) {
    for (const Rgba& c : {body.fill, outline_colour(body.fill)}) {
      palette.insert(palette.end(), c.channels.begin(), c.channels.end());
    }
  }
  auto texture_buffer = [&](GLuint& buffer, GLuint& texture, const std::vector<float>& data,
                            GLenum usage) {
    gl_.GenBuffers(1, &buffer);
    gl_.BindBuffer(GL_TEXTURE_BUFFER, buffer);
    gl_.BufferData(GL_TEXTURE_BUFFER,
                   static_cast<GLsizeiptr>(std::max<std::size_t>(data.size(), 8) * sizeof(float)),
                   data.empty() ? nullptr : data.data(), usage);
    gl_.GenTextures(1, &texture);
    gl_.BindTexture(GL_TEXTURE_BUFFER, texture);
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer);
  };
  texture_buffer(g.transform_buffer, g.transform_texture, g.transforms, GL_STREAM_DRAW);
  texture_buffer(g.palette_buffer, g.palette_texture, palette, GL_STATIC_DRAW);
}

void SceneRenderer::create_targets() {
  GpuState& g = *gpu_;
  const int w = context_.width();
  const int h = context_.height();
  const bool msaa = settings_.anti_aliasing == AntiAliasing::kMsaa;
  if (msaa) {
    GLint samples = 0;
    gl_.GetIntegerv(GL_MAX_INTEGER_SAMPLES, &samples);
    if (samples < kMsaaSamples) {
      throw GlUnavailable(
          "renderer: this GL has no 4x MSAA of integer targets (anti-aliasing "
          "\"shader\" needs none)");
    }
  }
  const GLenum id_target = msaa ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
  gl_.GenTextures(1, &g.id_texture);
  gl_.BindTexture(id_target, g.id_texture);
  if (msaa) {
    gl_.TexStorage2DMultisample(id_target, kMsaaSamples, GL_R16UI, w, h, GL_TRUE);
  } else {
    gl_.TexStorage2D(id_target, 1, GL_R16UI, w, h);
    gl_.TexParameteri(id_target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(id_target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  gl_.GenFramebuffers(1, &g.id_framebuffer);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, g.id_framebuffer);
  gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, id_target, g.id_texture, 0);
  if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw GlUnavailable("renderer: the body-index target is incomplete");
  }
  if (msaa) {
    gl_.GenRenderbuffers(1, &g.msaa_colour);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, g.msaa_colour);
    gl_.RenderbufferStorageMultisample(GL_RENDERBUFFER, kMsaaSamples, GL_RGBA8, w, h);
    gl_.GenFramebuffers(1, &g.msaa_framebuffer);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, g.msaa_framebuffer);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                g.msaa_colour);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw GlUnavailable("renderer: the multisampled colour target is incomplete");
    }
  }
}

void SceneRenderer::upload_transforms(const FrameSnapshot& frame) {
  GpuState& g = *gpu_;
  if (frame.bodies.size() != bodies_.size()) {
    throw std::invalid_argument("renderer: the snapshot has " +
                                std::to_string(frame.bodies.size()) + " bodies, the scene " +
                                std::to_string(bodies_.size()));
  }
  const Camera& camera = settings_.camera;
  // World → normalised device coordinates, upside down (so rows come out top first), composed
  // with each placement in double precision: a kilometre-wide world keeps its millimetres.
  const double sx = 2.0 / camera.width();
  const double sy = -2.0 / camera.height;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Transform2& t = frame.bodies[b].placement;
    const Vec2 offset = t.translation() - camera.center;
    float* out = &g.transforms[8 * b];
    out[0] = static_cast<float>(sx * t.cos_angle());  // column 0
    out[1] = static_cast<float>(sy * t.sin_angle());
    out[2] = static_cast<float>(-sx * t.sin_angle());  // column 1
    out[3] = static_cast<float>(sy * t.cos_angle());
    out[4] = static_cast<float>(sx * offset.x());
    out[5] = static_cast<float>(sy * offset.y());
    out[6] = 0.f;
    out[7] = 0.f;
  }
  gl_.BindBuffer(GL_TEXTURE_BUFFER, g.transform_buffer);
  gl_.BufferSubData(GL_TEXTURE_BUFFER, 0,
                    static_cast<GLsizeiptr>(g.transforms.size() * sizeof(float)),
                    g.transforms.data());
}

void SceneRenderer::draw(const FrameSnapshot& frame) {
  GpuState& g = *gpu_;
  const bool msaa = settings_.anti_aliasing == AntiAliasing::kMsaa;
  const float fringe = settings_.anti_aliasing == AntiAliasing::kShader ? 1.f : 0.f;
  const double scale = std::max(1.0, settings_.camera.height_px / 720.0);
  context_.make_current();
  upload_transforms(frame);
  gl_.Viewport(0, 0, context_.width(), context_.height());
  gl_.Disable(GL_BLEND);

  // 1. Fills: body index by XOR.
  gl_.BindFramebuffer(GL_FRAMEBUFFER, g.id_framebuffer);
  const GLuint zero[4] = {0, 0, 0, 0};
  gl_.ClearBufferuiv(GL_COLOR, 0, zero);
  gl_.Enable(GL_COLOR_LOGIC_OP);
  gl_.LogicOp(GL_XOR);
  g.fill.use();
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.transform_texture);
  gl_.Uniform1i(g.fill.uniform("transforms"), 0);
  gl_.BindVertexArray(g.fill_vao);
  gl_.DrawArrays(GL_TRIANGLES, 0, g.fill_count);
  gl_.Disable(GL_COLOR_LOGIC_OP);

  // 2. Background by a clear (the cheapest way to fill pixels), then body index → colour over
  // each body's box only.
  gl_.BindFramebuffer(GL_FRAMEBUFFER, msaa ? g.msaa_framebuffer : context_.framebuffer());
  const auto& bg = settings_.background.channels;
  const GLfloat background[4] = {bg[0], bg[1], bg[2], 1.f};
  gl_.ClearBufferfv(GL_COLOR, 0, background);
  g.resolve.use();
  gl_.ActiveTexture(GL_TEXTURE2);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.transform_texture);
  gl_.Uniform1i(g.resolve.uniform("transforms"), 2);
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(msaa ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, g.id_texture);
  gl_.Uniform1i(g.resolve.uniform("ids"), 0);
  gl_.ActiveTexture(GL_TEXTURE1);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.palette_texture);
  gl_.Uniform1i(g.resolve.uniform("palette"), 1);
  gl_.BindVertexArray(g.bounds_vao);
  gl_.DrawArrays(GL_TRIANGLES, 0, g.bounds_count);

  // 3. Outlines, blended over the fills.
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  g.outline.use();
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.transform_texture);
  gl_.Uniform1i(g.outline.uniform("transforms"), 0);
  gl_.ActiveTexture(GL_TEXTURE1);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.palette_texture);
  gl_.Uniform1i(g.outline.uniform("palette"), 1);
  const bool by_lambda = settings_.overlays.rugosity;
  const double width = settings_.outline_px * scale * (by_lambda ? 2.0 : 1.0);
  gl_.Uniform1f(g.outline.uniform("metres_per_pixel"),
                static_cast<float>(settings_.camera.pixel_size()));
  gl_.Uniform1f(g.outline.uniform("half_width"), static_cast<float>(0.5 * width));
  gl_.Uniform1f(g.outline.uniform("fringe"), fringe);
  gl_.Uniform1i(g.outline.uniform("colour_by_lambda"), by_lambda ? 1 : 0);
  gl_.BindVertexArray(g.outline_vao);
  gl_.DrawArrays(GL_TRIANGLES, 0, g.outline_count);

  // 4. Overlays.
  if (settings_.overlays.contacts || settings_.overlays.velocity) {
    overlay_builder_.clear();
    overlay_builder_.add_frame(frame, fixed_, settings_.overlays);
    const std::vector<OverlayVertex>& v = overlay_builder_.vertices();
    if (!v.empty()) {
      gl_.BindVertexArray(g.overlay_vao);
      gl_.BindBuffer(GL_ARRAY_BUFFER, g.overlay_vbo);
      const auto bytes = static_cast<GLsizeiptr>(v.size() * sizeof(OverlayVertex));
      if (v.size() > g.overlay_capacity) {
        g.overlay_capacity = v.size() * 2;
        gl_.BufferData(GL_ARRAY_BUFFER,
                       static_cast<GLsizeiptr>(g.overlay_capacity * sizeof(OverlayVertex)), nullptr,
                       GL_STREAM_DRAW);
      }
      gl_.BufferSubData(GL_ARRAY_BUFFER, 0, bytes, v.data());
      g.overlay.use();
      gl_.Uniform1f(g.overlay.uniform("fringe"), fringe);
      gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
    }
  }
  gl_.Disable(GL_BLEND);
  gl_.BindVertexArray(0);

  if (msaa) {
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, g.msaa_framebuffer);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, context_.framebuffer());
    gl_.BlitFramebuffer(0, 0, context_.width(), context_.height(), 0, 0, context_.width(),
                        context_.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  const GLenum error = gl_.GetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error("renderer: OpenGL error " + std::to_string(error) +
                             " while drawing frame " + std::to_string(frame.frame));
  }
}

void SceneRenderer::read(Image& image) const {
  image.width = context_.width();
  image.height = context_.height();
  image.rgba.resize(Image::bytes(image.width, image.height));
  context_.make_current();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, context_.framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // The frame was drawn upside down, so GL's bottom-up rows are the image's top-down rows.
  gl_.ReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
}

}  // namespace rugosim
