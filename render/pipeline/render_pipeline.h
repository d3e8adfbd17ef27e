// The render pipeline (DESIGN.md, "Data flow"): the simulation, the renderer and the sink each
// run on a thread of their own, linked by bounded queues, so that on a machine with cores to
// spare rendering hides behind encoding. Frames reach the sink in order.
//
// Interruption (SIGINT): the simulation stops producing, the renderer finishes the frame in
// hand, the sink gets every frame rendered, and the caller closes the sink: what was done stays
// readable. An exception in any stage stops the others and is rethrown to the caller.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

#include "engine/dynamics/frame_snapshot.h"
#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim {

// Draws snapshots into images; made on, and used from, the render thread only (a GL context is
// current on one thread).
class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  virtual void render(const FrameSnapshot& frame, Image& image) = 0;
};

struct PipelineStages {
  // The next snapshot to draw, or nullopt when the clip is done (simulation thread).
  std::function<std::optional<FrameSnapshot>()> next_snapshot;
  // Makes the renderer (render thread, once); null ends the run early without an error (the
  // caller was interrupted before it could say how to draw).
  std::function<std::unique_ptr<FrameRenderer>()> make_renderer;
  // Takes every image in order (sink thread: the caller's). It may keep nothing: the image is
  // reused for a later frame once this returns.
  std::function<void(const Image& image, std::size_t frame)> consume;
  // Set from a signal handler (or another thread) to stop early.
  const std::atomic<bool>* interrupted = nullptr;
  std::size_t snapshots_ahead = 8;   // snapshots the simulation may run ahead
  std::size_t images_in_flight = 3;  // images between renderer and sink
};

struct PipelineResult {
  std::size_t frames = 0;    // frames consumed
  bool interrupted = false;  // stopped by `interrupted`
};

PipelineResult run_pipeline(const PipelineStages& stages);

// A sink as a pipeline's consumer.
inline std::function<void(const Image&, std::size_t)> consume_into(FrameSink& sink) {
  return [&sink](const Image& image, std::size_t frame) { sink.write(image, frame); };
}

}  // namespace rugosim
