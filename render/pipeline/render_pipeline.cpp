#include "render/pipeline/render_pipeline.h"

#include <atomic>
#include <thread>
#include <utility>

#include "render/bounded_queue.h"
#include "render/first_error.h"

namespace rugosim {
namespace {

struct RenderedFrame {
  Image image;
  std::size_t frame = 0;
};

}  // namespace

PipelineResult run_pipeline(const PipelineStages& stages) {
  BoundedQueue<FrameSnapshot> snapshots(stages.snapshots_ahead);
  BoundedQueue<RenderedFrame> rendered(stages.images_in_flight);
  BoundedQueue<Image> spare(stages.images_in_flight + 1);  // images to reuse
  for (std::size_t i = 0; i < stages.images_in_flight + 1; ++i)
    spare.push(Image());
  FirstError error;
  std::atomic<bool> stop{false};
  auto interrupted = [&] {
    return stages.interrupted != nullptr && stages.interrupted->load(std::memory_order_relaxed);
  };
  auto halt = [&] {
    stop = true;
    snapshots.close();
    rendered.close();
    spare.close();
  };

  std::thread simulation([&] {
    try {
      while (!stop && !interrupted()) {
        std::optional<FrameSnapshot> next = stages.next_snapshot();
        if (!next || !snapshots.push(std::move(*next))) break;
      }
    } catch (...) {
      error.capture();
      halt();
    }
    snapshots.close();
  });

  std::thread renderer_thread([&] {
    try {
      std::unique_ptr<FrameRenderer> renderer = stages.make_renderer();
      // After an interruption the frame in hand is finished and passed on; queued ones are not.
      while (renderer && !stop && !interrupted()) {
        std::optional<FrameSnapshot> snapshot = snapshots.pop();
        if (!snapshot) break;
        std::optional<Image> image = spare.pop();
        if (!image) break;
        renderer->render(*snapshot, *image);
        if (!rendered.push(RenderedFrame{std::move(*image), snapshot->frame})) break;
      }
    } catch (...) {
      error.capture();
      halt();
    }
    // The simulation may be waiting on a full queue: let it go.
    snapshots.close();
    rendered.close();
  });

  PipelineResult result;
  try {
    while (std::optional<RenderedFrame> frame = rendered.pop()) {
      stages.consume(frame->image, frame->frame);
      ++result.frames;
      spare.push(std::move(frame->image));
    }
  } catch (...) {
    error.capture();
    halt();
  }
  simulation.join();
  renderer_thread.join();
  error.rethrow();
  result.interrupted = interrupted();
  return result;
}

}  // namespace rugosim
