// Rendering a clip of a loaded scene, shared by `render` and `snapshot`: the World simulated
// through every frame time, the chosen frames drawn on the render pipeline's threads
// (render/pipeline), each image handed to the caller in order.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/aabb.h"
#include "render/app/scene_input.h"
#include "render/draw/scene_renderer.h"
#include "render/gl/gl_context.h"
#include "render/image.h"
#include "render/pipeline/render_pipeline.h"
#include "render/text/frame_text.h"

namespace rugosim::app {

struct ClipPlan {
  std::vector<std::size_t> frames;  // frame numbers to draw, increasing
  double fps = 30.0;                // frame k is the state at t = k / fps
  int width = 0;                    // px
  int height = 0;                   // px
  GlBackend backend = GlBackend::kOsmesa;
  AntiAliasing anti_aliasing = AntiAliasing::kShader;
  Overlays overlays;
  // A chunk of a longer clip (render_chunk.h): the frame whose time the World is at (restored
  // from a checkpoint), and with the automatic camera, every body's box over the whole clip.
  std::size_t start_reached = 0;
  std::optional<Aabb> clip_bounds;
};

// llvmpipe's rasteriser threads (LP_NUM_THREADS), read by Mesa when the first context starts:
// `threads`, or by default none (the render thread rasterises alone; see the .cpp). An
// LP_NUM_THREADS the user set is kept unless `threads` is given. Call before any context.
void choose_rasteriser_threads(const std::optional<int>& threads);

// Simulates `loaded`'s World from its current state and draws plan.frames, calling `consume`
// with each image (on the calling thread, in order). The camera is the scene's, or with "auto"
// the one that frames every body over the frames drawn. Stops early when `interrupted` is set.
// Throws what a stage throws (GlUnavailable, std::runtime_error from the consumer...).
// `renderer`, when given, receives GlContext::renderer() (Mesa version, backend).
PipelineResult render_clip(LoadedScene& loaded, const ClipPlan& plan,
                           const std::function<void(const Image&, std::size_t)>& consume,
                           const std::atomic<bool>* interrupted, std::string* renderer = nullptr);

// One frame, plan.frames[0], as a vector writer needs it (render/sinks/vector_still.h): the
// snapshot, the looks and the settings (camera included) the raster path would draw it with,
// and its text. nullopt when `interrupted` stopped the simulation first.
struct StillFrame {
  FrameSnapshot frame;
  std::vector<BodyLook> looks;
  RenderSettings settings;
  FrameText text;
};
std::optional<StillFrame> simulate_still(LoadedScene& loaded, const ClipPlan& plan,
                                         const std::atomic<bool>* interrupted);

}  // namespace rugosim::app
