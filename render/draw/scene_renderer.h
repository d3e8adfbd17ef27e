// Draws frames of a scene off-screen (DESIGN.md, "Rendering"). Every body's detailed outline
// (rugosity_detail.h) is made and uploaded once, in the body's frame; each frame sends only the
// bodies' transforms and the overlays, and draws everything in three batched calls:
//   1. fills: the background cleared, then every body's parity triangles XORed on in one draw
//      (shaders/body_fill.frag says why that fills concave outlines exactly);
//   2. outlines: quads along every outline, in the body's colour or by λ (overlay `rugosity`);
//   3. overlays: contacts and velocities.
// Edges are anti-aliased either by the shaders (coverage ramps on outlines and overlays, which
// cover the fills' edges) or by 4× MSAA of every pass.
//
// Incremental redraw: the framebuffer keeps the last frame, and when only some bodies moved
// (no contact or velocity overlay, no MSAA) only the window rectangles they covered then or
// cover now are cleared and drawn again (dirty_rects.h), each with just the runs of triangles
// that reach it (mesh_chunks.h). Every pixel outside them is already what a full redraw would
// give, and inside them every triangle that covers a pixel is drawn, in the same order, so the
// picture is bit for bit that of a full redraw (tested); a still floor or container costs
// nothing once drawn. This relies on the framebuffer holding what this renderer drew last:
// give each renderer a context of its own (or draw nothing else into it between frames).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/dynamics/frame_snapshot.h"
#include "engine/geometry/periodic_bspline.h"
#include "render/color.h"
#include "render/draw/camera.h"
#include "render/draw/dirty_rects.h"
#include "render/draw/mesh_chunks.h"
#include "render/draw/overlay_geometry.h"
#include "render/draw/rugosity_detail.h"
#include "render/gl/gl_context.h"
#include "render/image.h"

namespace rugosim {

enum class AntiAliasing { kShader, kMsaa, kNone };
std::optional<AntiAliasing> parse_anti_aliasing(std::string_view name);  // "shader", "msaa", "none"
std::string_view anti_aliasing_name(AntiAliasing aa);

// How one body looks: its curve (the body frame the snapshot's placement maps to the world),
// σ and λ per segment of that curve, colours, and the seed of its detail.
struct BodyLook {
  PeriodicBSpline curve;
  std::vector<double> sigma;   // m, one per segment
  std::vector<double> lambda;  // m, one per segment (colours the `rugosity` overlay)
  Rgba fill;
  bool fixed = false;
  std::uint64_t seed = 0;
  std::optional<Rgba> outline;  // the outline's colour; none: the fill darkened
};

struct RenderSettings {
  Camera camera;    // its pixel size sets the detail; width_px × height_px must be the context's
  Rgba background;  // opaque, or (0, 0, 0, 0): none (images then carry straight alpha)
  AntiAliasing anti_aliasing = AntiAliasing::kShader;
  Overlays overlays;
  double outline_px = 1.5;  // px at 720 lines; scaled with the frame's height
  DetailSettings detail;    // pixel_size is taken from the camera
  bool incremental = true;  // redraw only where bodies moved (the same pixels as a full redraw)
};

class SceneRenderer {
 public:
  // Throws GlUnavailable when the context cannot do what the settings ask (e.g. MSAA of an
  // integer target), std::invalid_argument for a camera of another size than the context.
  SceneRenderer(GlContext& context, std::vector<BodyLook> bodies, const RenderSettings& settings);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Draws the frame into the context's framebuffer, unless it would give the picture already
  // there (every placement, and what the overlays show, bit for bit the same): a scene at rest
  // costs a read back per frame. Throws std::runtime_error on a GL error.
  void draw(const FrameSnapshot& frame);
  // Frames draw() found unchanged and did not draw.
  std::size_t frames_reused() const { return frames_reused_; }
  // Frames draw() redrew only in part, and the pixels it cleared and drew again for them.
  std::size_t frames_partial() const { return frames_partial_; }
  std::int64_t pixels_redrawn() const { return pixels_redrawn_; }
  // Reads what draw() made, rows top first, and numbers the image with the picture
  // (Image::picture); an image that already holds this picture is left as it is.
  void read(Image& image) const;
  // The number of the picture in the framebuffer: a new one each time draw() draws.
  std::uint64_t picture() const { return picture_; }
  Image render(const FrameSnapshot& frame) {
    draw(frame);
    Image image;
    read(image);
    return image;
  }

  // Points per body outline as generated (the detail level chosen for the camera).
  const std::vector<DetailOutline>& outlines() const { return outlines_; }

 private:
  struct GpuState;
  void build_meshes();
  void create_targets();
  void upload_transforms(const FrameSnapshot& frame);
  bool same_picture(const FrameSnapshot& frame) const;
  // The rectangles to redraw after last_drawn_, or nullopt for the whole frame.
  std::optional<std::vector<PixelRect>> dirty_rects(const FrameSnapshot& frame) const;
  // Clears and draws the fills, outlines and overlays: everywhere when `rect` is null, else
  // inside it with the chunks that reach it (placed_fill_ and placed_outline_, this frame's).
  void draw_pass(const FrameSnapshot& frame, const PixelRect* rect);

  GlContext& context_;
  const GlApi& gl_;
  std::vector<BodyLook> bodies_;
  RenderSettings settings_;
  std::vector<DetailOutline> outlines_;
  std::vector<bool> fixed_;
  float half_width_ = 0.f;  // px, half the outline's visible width
  float fringe_ = 0.f;      // px of anti-aliasing ramp beyond it
  std::vector<MeshChunk> fill_chunks_, outline_chunks_;
  std::vector<Aabb> body_reach_;  // m, body frame: everything a body's triangles can cover
  std::vector<PixelRect> placed_fill_, placed_outline_;  // the chunks' rectangles this frame
  OverlayBuilder overlay_builder_;
  std::optional<FrameSnapshot> last_drawn_;
  std::size_t frames_reused_ = 0;
  std::uint64_t picture_ = 0;
  std::size_t frames_partial_ = 0;
  std::int64_t pixels_redrawn_ = 0;
  std::unique_ptr<GpuState> gpu_;
};

}  // namespace rugosim
