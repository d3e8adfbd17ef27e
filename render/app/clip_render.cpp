#include "render/app/clip_render.h"

#include <cstdlib>
#include <future>
#include <memory>
#include <string>

#include "engine/dynamics/frame_snapshot.h"
#include "engine/scene/scene_loader.h"
#include "render/app/render_scene.h"
#include "render/draw/camera.h"

namespace rugosim::app {
namespace {

// The renderer of the render thread: its own GL context and scene renderer.
class ContextRenderer final : public FrameRenderer {
 public:
  ContextRenderer(std::unique_ptr<GlContext> context, std::vector<BodyLook> looks,
                  const RenderSettings& settings, FrameText text)
      : context_(std::move(context)),
        renderer_(*context_, std::move(looks), settings),
        metres_per_pixel_(settings.camera.pixel_size()),
        text_(std::move(text)) {}
  void render(const FrameSnapshot& frame, Image& image) override {
    renderer_.draw(frame);
    renderer_.read(image);
    text_.paint(image, frame.time, metres_per_pixel_);
  }

 private:
  std::unique_ptr<GlContext> context_;
  SceneRenderer renderer_;
  double metres_per_pixel_;
  FrameTextPainter text_;  // draws nothing (and opens no font) without text
};

// The snapshots of the clip, made on the simulation thread. With an explicit camera each frame
// is simulated when asked for. With "auto" the whole clip is simulated at the first call (the
// snapshots are small), the camera that frames every body over all of it is published to the
// render thread, and the stored snapshots are handed out.
class ClipSource {
 public:
  // `follow`: the body every snapshot is centred on (centred_on), for a following camera.
  ClipSource(World& world, const ClipPlan& plan, std::optional<Camera> camera,
             std::optional<std::size_t> follow, const std::atomic<bool>* interrupted)
      : world_(world),
        plan_(plan),
        automatic_(!camera),
        follow_(follow),
        interrupted_(interrupted),
        reached_(plan.start_reached) {
    // Every step polls the flag: a run crawling through short steps stops within one.
    world_.set_stop_flag(interrupted);
    if (camera) camera_.set_value(camera);
  }

  std::optional<FrameSnapshot> next() {
    if (!automatic_) return simulate_next();
    if (!simulated_) simulate_clip();
    if (handed_ >= clip_.size()) return std::nullopt;
    return std::move(clip_[handed_++]);
  }

  // Blocks until the camera is known; nullopt when the simulation was interrupted first.
  std::optional<Camera> camera() { return camera_future_.get(); }

 private:
  // The World passes through every frame time of the clip, drawn or not: a step ends at each
  // time it is asked for, so stopping only at the drawn frames would give another trajectory
  // (a strip's frames or a --frames range must look exactly as in the whole clip, and as in
  // `simulate` at the same fps). The events kept are those since the previous frame time.
  std::optional<FrameSnapshot> simulate_next() {
    if (next_ >= plan_.frames.size()) return std::nullopt;
    const std::size_t frame = plan_.frames[next_++];
    for (; reached_ < frame; ++reached_) {
      world_.clear_events();
      world_.advance_to(static_cast<double>(reached_ + 1) / plan_.fps);
      if (world_.stop_requested()) return std::nullopt;  // stopped short of the frame's time
    }
    FrameSnapshot snapshot = take_snapshot(world_, frame);
    world_.clear_events();
    if (follow_) return centred_on(std::move(snapshot), *follow_);
    return snapshot;
  }

  void simulate_clip() {
    simulated_ = true;
    try {
      while (std::optional<FrameSnapshot> snapshot = simulate_next()) {
        if (interrupted_ != nullptr && interrupted_->load()) break;
        clip_.push_back(std::move(*snapshot));
      }
      if (interrupted_ != nullptr && interrupted_->load()) {
        clip_.clear();
        camera_.set_value(std::nullopt);
        return;
      }
      camera_.set_value(fit_clip_camera(world_, clip_, plan_.width, plan_.height));
    } catch (...) {
      camera_.set_exception(std::current_exception());
      throw;
    }
  }

  World& world_;
  const ClipPlan& plan_;
  bool automatic_;
  std::optional<std::size_t> follow_;
  const std::atomic<bool>* interrupted_;
  std::promise<std::optional<Camera>> camera_;
  std::future<std::optional<Camera>> camera_future_ = camera_.get_future();
  std::size_t next_ = 0;
  std::size_t reached_;  // the frame whose time the World is at
  bool simulated_ = false;
  std::vector<FrameSnapshot> clip_;
  std::size_t handed_ = 0;
};

}  // namespace

// By default none: the cores are better spent on the encoder (x264's threads, the PNG workers)
// and the simulation. Measured on 2 cores (bench/render_bench.cpp): with incremental redraw the
// 151 frames of figure12a to MP4 at 720p take 1.01-1.06 s with none and 1.01-1.12 s with two,
// no gain for the competition with x264's threads.
void choose_rasteriser_threads(const std::optional<int>& threads) {
  if (threads) {
    ::setenv("LP_NUM_THREADS", std::to_string(*threads).c_str(), 1);
  } else {
    ::setenv("LP_NUM_THREADS", "0", 0);
  }
}

namespace {

// The scene's look for the clip; the camera is set when it is known.
RenderSettings clip_settings(const LoadedScene& loaded, const ClipPlan& plan) {
  RenderSettings settings;
  settings.background = scene_background(loaded.scene);
  settings.outline_px = scene_outline_px(loaded.scene);
  settings.detail = scene_detail(loaded.scene);
  settings.anti_aliasing = plan.anti_aliasing;
  settings.overlays = plan.overlays;
  return settings;
}

// The clip's snapshots with the scene's camera: fixed, following a body, or automatic.
ClipSource clip_source(LoadedScene& loaded, const ClipPlan& plan,
                       const std::atomic<bool>* interrupted) {
  World& world = *loaded.world;
  std::optional<Camera> fixed_camera = scene_camera(loaded.scene, plan.width, plan.height);
  const CameraSpec& spec = loaded.scene.render.camera;
  const std::optional<std::size_t> follow =
      spec.follow.empty() ? std::nullopt : find_body(loaded.scene, spec.follow);
  if (follow) fixed_camera = follow_camera(world, *follow, spec.height, plan.width, plan.height);
  // A chunk's automatic camera: the whole clip's framing, as fit_clip_camera finds it.
  if (spec.automatic && plan.clip_bounds)
    fixed_camera = fit_camera(*plan.clip_bounds, plan.width, plan.height);
  return ClipSource(world, plan, fixed_camera, follow, interrupted);
}

}  // namespace

std::optional<StillFrame> simulate_still(LoadedScene& loaded, const ClipPlan& plan,
                                         const std::atomic<bool>* interrupted) {
  StillFrame still;
  still.settings = clip_settings(loaded, plan);
  still.looks = body_looks(loaded.scene, *loaded.world);
  ClipSource source = clip_source(loaded, plan, interrupted);
  std::optional<FrameSnapshot> frame = source.next();
  const std::optional<Camera> camera = source.camera();
  if (!frame || !camera) return std::nullopt;
  still.frame = std::move(*frame);
  still.settings.camera = *camera;
  still.text = frame_text(loaded.scene, still.looks, plan.overlays);
  return still;
}

PipelineResult render_clip(LoadedScene& loaded, const ClipPlan& plan,
                           const std::function<void(const Image&, std::size_t)>& consume,
                           const std::atomic<bool>* interrupted, std::string* renderer) {
  const RenderSettings settings = clip_settings(loaded, plan);
  ClipSource source = clip_source(loaded, plan, interrupted);
  // Made before the threads start: the simulation thread moves the bodies.
  const std::vector<BodyLook> looks = body_looks(loaded.scene, *loaded.world);

  PipelineStages stages;
  stages.next_snapshot = [&] { return source.next(); };
  stages.make_renderer = [&]() -> std::unique_ptr<FrameRenderer> {
    // The context starts (Mesa, shaders) while the simulation runs; the meshes wait for the
    // camera, whose pixel size sets their detail.
    std::unique_ptr<GlContext> context = GlContext::create(plan.backend, plan.width, plan.height);
    if (renderer != nullptr) *renderer = context->renderer();  // read after the threads join
    const std::optional<Camera> camera = source.camera();
    if (!camera) return nullptr;  // interrupted before the clip was simulated
    RenderSettings with_camera = settings;
    with_camera.camera = *camera;
    return std::make_unique<ContextRenderer>(std::move(context), looks, with_camera,
                                             frame_text(loaded.scene, looks, plan.overlays));
  };
  stages.consume = consume;
  stages.interrupted = interrupted;
  return run_pipeline(stages);
}

}  // namespace rugosim::app
