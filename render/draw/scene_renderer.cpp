#include "render/draw/scene_renderer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/geometry/tolerance_profile.h"
#include "render/draw/palette.h"
#include "render/draw/parity_fill.h"
#include "render/draw/shader_program.h"

namespace rugosim {
namespace {

constexpr int kMsaaSamples = 4;
// Incremental redraw: pixels of slack around every rectangle, for the GPU's float arithmetic
// (far below a pixel); what one more pass costs, counted in pixels of a larger rectangle; at
// most this many passes; and past this share of the frame, a full redraw.
constexpr int kDirtyMarginPx = 2;
constexpr std::int64_t kPassCostPx = 128 * 128;
constexpr std::size_t kMaxPasses = 6;
constexpr double kFullRedrawShare = 0.6;
// More moved bodies than this, and the frame is drawn whole without merging their rectangles
// (merging is quadratic in their number, and so many rarely leave much of the frame alone).
constexpr std::size_t kMaxMovedBodies = 64;

// Picture numbers, unique in the process (Image::picture): two renderers never share one.
std::atomic<std::uint64_t> next_picture{1};
constexpr std::size_t kMaxBodies = std::size_t{1} << 22;  // indices exact in shader arithmetic

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

// The colour whose XOR with the background, byte by byte, is `fill`, opaque: over an opaque
// background the key's alpha is 0 (XOR leaves the cleared alpha of 1), over a transparent one
// it is 1.
Rgba xor_key(const Rgba& background, const Rgba& fill) {
  Rgba key;
  for (std::size_t c = 0; c < 3; ++c) {
    const auto a = static_cast<unsigned>(std::lround(background.channels[c] * 255.f));
    const auto b = static_cast<unsigned>(std::lround(fill.channels[c] * 255.f));
    key.channels[c] = static_cast<float>(a ^ b) / 255.f;
  }
  const auto alpha = static_cast<unsigned>(std::lround(background.channels[3] * 255.f));
  key.channels[3] = static_cast<float>(alpha ^ 255u) / 255.f;
  return key;
}

// Over a transparent background the framebuffer holds premultiplied colour: the outlines and
// overlays blend (source alpha, one minus source alpha) onto (0, 0, 0, 0), and the fills are
// opaque. Images carry straight alpha (as PNG, WebM and ProRes do): divide it out.
void unpremultiply(Image& image) {
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const unsigned alpha = image.rgba[i + 3];
    if (alpha == 255) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const unsigned straight =
          alpha == 0 ? 0u : std::min(255u, (image.rgba[i + c] * 255u + alpha / 2) / alpha);
      image.rgba[i + c] = static_cast<std::uint8_t>(straight);
    }
  }
}

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

// The element buffer of the bound vertex array.
void upload_indices(const GlApi& gl, GLuint& buffer, const std::vector<std::uint32_t>& indices) {
  gl.GenBuffers(1, &buffer);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                GL_STATIC_DRAW);
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
  explicit GpuState(const GlApi& gl)
      : fill(gl, "body_fill.vert", "body_fill.frag"),
        outline(gl, "outline.vert", "outline.frag"),
        overlay(gl, "overlay.vert", "overlay.frag") {}

  ShaderProgram fill;
  ShaderProgram outline;
  ShaderProgram overlay;
  GLuint fill_vao = 0, fill_vbo = 0, fill_ibo = 0;
  GLsizei fill_count = 0;
  GLuint outline_vao = 0, outline_vbo = 0, outline_ibo = 0;
  GLsizei outline_count = 0;
  GLuint overlay_vao = 0, overlay_vbo = 0;
  std::size_t overlay_capacity = 0;  // vertices the overlay buffer holds
  GLuint transform_buffer = 0, transform_texture = 0;
  GLuint palette_buffer = 0, palette_texture = 0;
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
    throw std::invalid_argument("renderer: at most 4,194,304 bodies can be drawn");
  }
  settings_.detail.pixel_size = settings_.camera.pixel_size();
  const double scale = std::max(1.0, settings_.camera.height_px / 720.0);
  const bool by_lambda = settings_.overlays.rugosity;
  const double width = settings_.outline_px * scale * (by_lambda ? 2.0 : 1.0);
  half_width_ = static_cast<float>(0.5 * width);
  fringe_ = settings_.anti_aliasing == AntiAliasing::kShader ? 1.f : 0.f;
  context_.make_current();
  gpu_ = std::make_unique<GpuState>(gl_);
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
  const GLuint arrays[] = {g.fill_vao, g.outline_vao, g.overlay_vao};
  gl_.DeleteVertexArrays(3, arrays);
  const GLuint buffers[] = {g.fill_vbo,    g.fill_ibo,         g.outline_vbo,   g.outline_ibo,
                            g.overlay_vbo, g.transform_buffer, g.palette_buffer};
  gl_.DeleteBuffers(7, buffers);
  const GLuint textures[] = {g.transform_texture, g.palette_texture};
  gl_.DeleteTextures(2, textures);
  gl_.DeleteFramebuffers(1, &g.msaa_framebuffer);
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
  // Indexed: each outline point is one fill vertex and two outline vertices, shaded once per
  // frame (llvmpipe's vertex stage runs on one thread).
  std::vector<FillVertex> fill;
  std::vector<std::uint32_t> fill_indices;
  std::vector<OutlineVertex> outline;
  std::vector<std::uint32_t> outline_indices;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const BodyLook& body = bodies_[b];
    outlines_.push_back(make_detail_outline(body.curve, body.sigma, body.seed, settings_.detail));
    const std::vector<Vec2>& p = outlines_.back().points;
    const std::vector<double>& u = outlines_.back().param;
    const std::size_t n = p.size();
    const auto body_index = static_cast<std::uint32_t>(b);
    const ParityFill parity = parity_fill(p);
    const auto fill_base = static_cast<std::uint32_t>(fill.size());
    for (std::size_t i = 0; i <= n; ++i) {
      const Vec2& q = i < n ? p[i] : parity.anchor;
      fill.push_back(FillVertex{static_cast<float>(q.x()), static_cast<float>(q.y()), body_index});
    }
    for (const std::uint32_t i : parity.indices)
      fill_indices.push_back(fill_base + i);
    const auto ring = static_cast<std::uint32_t>(outline.size());  // two per point: in, out
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& q = p[i];
      const Vec2 m = miter(p[(i + n - 1) % n], q, p[(i + 1) % n]);
      const auto j = static_cast<std::size_t>(u[i]) % body.curve.size();
      const double lambda = profiles[b].at(j, u[i] - std::floor(u[i]));
      const float level = largest_lambda > 0.0 ? static_cast<float>(lambda / largest_lambda) : 0.f;
      for (const float side : {-1.f, 1.f}) {
        outline.push_back(OutlineVertex{static_cast<float>(q.x()), static_cast<float>(q.y()),
                                        body_index, static_cast<float>(m.x()),
                                        static_cast<float>(m.y()), side, level});
      }
    }
    const auto outline_first = static_cast<std::uint32_t>(outline_indices.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t k = (i + 1) % static_cast<std::uint32_t>(n);
      for (const std::uint32_t v : {2 * i, 2 * i + 1, 2 * k, 2 * k, 2 * i + 1, 2 * k + 1}) {
        outline_indices.push_back(ring + v);
      }
    }
    // The chunks' boxes hold the float positions the GPU draws, the outline's as the vertex
    // shader widens them.
    const auto fill_first = static_cast<std::uint32_t>(fill_indices.size() - parity.indices.size());
    const std::size_t first_fill_chunk = fill_chunks_.size();
    const std::size_t first_outline_chunk = outline_chunks_.size();
    append_chunks(
        fill_chunks_, body_index, fill_indices, fill_first,
        static_cast<std::uint32_t>(parity.indices.size()), [&](std::uint32_t v) {
          Aabb box;
          box.extend(Vec2(static_cast<double>(fill[v].x), static_cast<double>(fill[v].y)));
          return box;
        });
    const double reach_m =
        static_cast<double>(half_width_ + fringe_) * settings_.camera.pixel_size();
    append_chunks(
        outline_chunks_, body_index, outline_indices, outline_first,
        static_cast<std::uint32_t>(outline_indices.size()) - outline_first, [&](std::uint32_t v) {
          const OutlineVertex& o = outline[v];
          Aabb box;
          const double offset = static_cast<double>(o.side) * reach_m;
          box.extend(Vec2(static_cast<double>(o.x) + static_cast<double>(o.miter_x) * offset,
                          static_cast<double>(o.y) + static_cast<double>(o.miter_y) * offset));
          return box;
        });
    Aabb reach;
    for (std::size_t c = first_fill_chunk; c < fill_chunks_.size(); ++c)
      reach.extend(fill_chunks_[c].bounds);
    for (std::size_t c = first_outline_chunk; c < outline_chunks_.size(); ++c)
      reach.extend(outline_chunks_[c].bounds);
    body_reach_.push_back(reach);
  }
  g.fill_count = static_cast<GLsizei>(fill_indices.size());
  g.outline_count = static_cast<GLsizei>(outline_indices.size());

  gl_.GenVertexArrays(1, &g.fill_vao);
  gl_.BindVertexArray(g.fill_vao);
  gl_.GenBuffers(1, &g.fill_vbo);
  gl_.BindBuffer(GL_ARRAY_BUFFER, g.fill_vbo);
  gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(fill.size() * sizeof(FillVertex)),
                 fill.data(), GL_STATIC_DRAW);
  set_attribute(gl_, 0, 2, GL_FLOAT, sizeof(FillVertex), offsetof(FillVertex, x));
  set_attribute(gl_, 1, 1, GL_UNSIGNED_INT, sizeof(FillVertex), offsetof(FillVertex, body));
  upload_indices(gl_, g.fill_ibo, fill_indices);

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
  upload_indices(gl_, g.outline_ibo, outline_indices);

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

  // Per body: transform (2 texels, refilled each frame) and colours: fill, outline, and the key
  // the fill pass XORs onto the background (shaders/body_fill.frag), exact in 8 bits.
  g.transforms.assign(bodies_.size() * 8, 0.f);
  std::vector<float> palette;
  palette.reserve(bodies_.size() * 12);
  for (const BodyLook& body : bodies_) {
    for (const Rgba& c : {body.fill, body.outline.value_or(outline_colour(body.fill)),
                          xor_key(settings_.background, body.fill)}) {
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
    gl_.GetIntegerv(GL_MAX_SAMPLES, &samples);
    if (samples < kMsaaSamples) {
      throw GlUnavailable("renderer: this GL has no 4x MSAA (anti-aliasing \"shader\" needs none)");
    }
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

bool SceneRenderer::same_picture(const FrameSnapshot& frame) const {
  if (!last_drawn_ || last_drawn_->bodies.size() != frame.bodies.size()) return false;
  if (settings_.overlays.contacts && (!frame.events.empty() || !last_drawn_->events.empty())) {
    return false;
  }
  for (std::size_t i = 0; i < frame.bodies.size(); ++i) {
    const BodyPose& a = frame.bodies[i];
    const BodyPose& b = last_drawn_->bodies[i];
    if (a.placement.cos_angle() != b.placement.cos_angle() ||
        a.placement.sin_angle() != b.placement.sin_angle() ||
        a.placement.translation() != b.placement.translation()) {
      return false;
    }
    if (settings_.overlays.velocity && (a.velocity != b.velocity || a.asleep != b.asleep)) {
      return false;
    }
  }
  return true;
}

std::optional<std::vector<PixelRect>> SceneRenderer::dirty_rects(const FrameSnapshot& frame) const {
  // Contacts and velocities change nearly every frame all over it, and MSAA resolves the
  // whole frame: those are drawn whole.
  if (!settings_.incremental || settings_.anti_aliasing == AntiAliasing::kMsaa ||
      settings_.overlays.contacts || settings_.overlays.velocity || !last_drawn_ ||
      last_drawn_->bodies.size() != frame.bodies.size() || frame.bodies.size() != bodies_.size()) {
    return std::nullopt;
  }
  const Camera& camera = settings_.camera;
  std::vector<PixelRect> rects;
  for (std::size_t i = 0; i < frame.bodies.size(); ++i) {
    const Transform2& now = frame.bodies[i].placement;
    const Transform2& before = last_drawn_->bodies[i].placement;
    if (now.cos_angle() == before.cos_angle() && now.sin_angle() == before.sin_angle() &&
        now.translation() == before.translation()) {
      continue;
    }
    if (rects.size() >= 2 * kMaxMovedBodies) return std::nullopt;
    rects.push_back(window_rect(body_reach_[i], before, camera, kDirtyMarginPx));
    rects.push_back(window_rect(body_reach_[i], now, camera, kDirtyMarginPx));
  }
  std::vector<PixelRect> merged = merge_rects(std::move(rects), kPassCostPx, kMaxPasses);
  std::int64_t area = 0;
  for (const PixelRect& r : merged)
    area += r.area();
  const auto frame_area = static_cast<double>(camera.width_px) * camera.height_px;
  if (static_cast<double>(area) > kFullRedrawShare * frame_area) return std::nullopt;
  return merged;
}

void SceneRenderer::draw(const FrameSnapshot& frame) {
  // A scene at rest (every body asleep or still) keeps its last picture: nothing is drawn.
  if (same_picture(frame)) {
    ++frames_reused_;
    return;
  }
  const std::optional<std::vector<PixelRect>> rects = dirty_rects(frame);
  // Until this frame is drawn the framebuffer holds no frame that a later one can start from.
  last_drawn_.reset();
  picture_ = 0;
  context_.make_current();
  upload_transforms(frame);
  gl_.Viewport(0, 0, context_.width(), context_.height());
  if (!rects) {
    draw_pass(frame, nullptr);
  } else {
    std::vector<Transform2> placements;
    placements.reserve(frame.bodies.size());
    for (const BodyPose& pose : frame.bodies)
      placements.push_back(pose.placement);
    placed_fill_ = place_chunks(fill_chunks_, placements, settings_.camera, kDirtyMarginPx);
    placed_outline_ = place_chunks(outline_chunks_, placements, settings_.camera, kDirtyMarginPx);
    gl_.Enable(GL_SCISSOR_TEST);
    for (const PixelRect& rect : *rects) {
      draw_pass(frame, &rect);
      pixels_redrawn_ += rect.area();
    }
    gl_.Disable(GL_SCISSOR_TEST);
    ++frames_partial_;
  }
  GpuState& g = *gpu_;
  if (settings_.anti_aliasing == AntiAliasing::kMsaa) {
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
  last_drawn_ = frame;
  picture_ = next_picture.fetch_add(1, std::memory_order_relaxed);
}

void SceneRenderer::draw_pass(const FrameSnapshot& frame, const PixelRect* rect) {
  GpuState& g = *gpu_;
  const bool msaa = settings_.anti_aliasing == AntiAliasing::kMsaa;
  // The whole index buffer, or the chunks that reach the rectangle, in their order.
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  auto draw_triangles = [&](GLsizei whole, const std::vector<MeshChunk>& chunks,
                            const std::vector<PixelRect>& placed) {
    if (rect == nullptr) {
      gl_.DrawElements(GL_TRIANGLES, whole, GL_UNSIGNED_INT, nullptr);
      return;
    }
    counts.clear();
    offsets.clear();
    for (const IndexRange& r : select_chunks(chunks, placed, *rect)) {
      counts.push_back(static_cast<GLsizei>(r.count));
      offsets.push_back(reinterpret_cast<const void*>(std::size_t{r.first} * sizeof(GLuint)));
    }
    if (counts.empty()) return;
    gl_.MultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(),
                          static_cast<GLsizei>(counts.size()));
  };
  gl_.Disable(GL_BLEND);
  if (rect != nullptr) gl_.Scissor(rect->x0, rect->y0, rect->x1 - rect->x0, rect->y1 - rect->y0);

  // 1. Background by a clear, then every fill in one draw by XOR.
  gl_.BindFramebuffer(GL_FRAMEBUFFER, msaa ? g.msaa_framebuffer : context_.framebuffer());
  const auto& bg = settings_.background.channels;
  const GLfloat background[4] = {bg[0], bg[1], bg[2], bg[3]};
  gl_.ClearBufferfv(GL_COLOR, 0, background);
  gl_.Enable(GL_COLOR_LOGIC_OP);
  gl_.LogicOp(GL_XOR);
  g.fill.use();
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.transform_texture);
  gl_.Uniform1i(g.fill.uniform("transforms"), 0);
  gl_.ActiveTexture(GL_TEXTURE1);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.palette_texture);
  gl_.Uniform1i(g.fill.uniform("palette"), 1);
  gl_.BindVertexArray(g.fill_vao);
  draw_triangles(g.fill_count, fill_chunks_, placed_fill_);
  gl_.Disable(GL_COLOR_LOGIC_OP);

  // 2. Outlines, blended over the fills.
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  g.outline.use();
  gl_.ActiveTexture(GL_TEXTURE0);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.transform_texture);
  gl_.Uniform1i(g.outline.uniform("transforms"), 0);
  gl_.ActiveTexture(GL_TEXTURE1);
  gl_.BindTexture(GL_TEXTURE_BUFFER, g.palette_texture);
  gl_.Uniform1i(g.outline.uniform("palette"), 1);
  gl_.Uniform1f(g.outline.uniform("metres_per_pixel"),
                static_cast<float>(settings_.camera.pixel_size()));
  gl_.Uniform1f(g.outline.uniform("half_width"), half_width_);
  gl_.Uniform1f(g.outline.uniform("fringe"), fringe_);
  gl_.Uniform1i(g.outline.uniform("colour_by_lambda"), settings_.overlays.rugosity ? 1 : 0);
  gl_.BindVertexArray(g.outline_vao);
  draw_triangles(g.outline_count, outline_chunks_, placed_outline_);

  // 3. Overlays (never with a rectangle: see dirty_rects).
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
      gl_.Uniform1f(g.overlay.uniform("fringe"), fringe_);
      gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
    }
  }
  gl_.Disable(GL_BLEND);
  gl_.BindVertexArray(0);
}

void SceneRenderer::read(Image& image) const {
  if (picture_ != 0 && image.picture == picture_) return;  // a scene at rest: already there
  image.width = context_.width();
  image.height = context_.height();
  image.rgba.resize(Image::bytes(image.width, image.height));
  context_.make_current();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, context_.framebuffer());
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // The frame was drawn upside down, so GL's bottom-up rows are the image's top-down rows.
  gl_.ReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  if (settings_.background.channels[3] < 1.f) unpremultiply(image);
  image.picture = picture_;
}

}  // namespace rugosim
