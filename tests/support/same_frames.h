// Two renderers drawing the same clip, compared frame by frame (the incremental redraw's tests
// in tests/render and tests/app).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "engine/dynamics/frame_snapshot.h"
#include "render/draw/scene_renderer.h"

namespace rugosim::testing {

// The first frame (its number) whose pixels differ between `a` and `b`, or nullopt when every
// frame of `clip` is bit for bit the same.
inline std::optional<std::size_t> first_different_frame(SceneRenderer& a, SceneRenderer& b,
                                                        const std::vector<FrameSnapshot>& clip) {
  Image x, y;
  for (const FrameSnapshot& frame : clip) {
    a.draw(frame);
    a.read(x);
    b.draw(frame);
    b.read(y);
    if (x.rgba != y.rgba) return frame.frame;
  }
  return std::nullopt;
}

}  // namespace rugosim::testing
