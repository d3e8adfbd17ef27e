// Where a frame can differ from the frame drawn before it, for the scene renderer's incremental
// redraw (scene_renderer.h): the window rectangles that the moved bodies covered then or cover
// now. Outside them the earlier picture is already the new one, so only these are cleared and
// drawn again.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/core/aabb.h"
#include "engine/core/transform.h"
#include "render/draw/camera.h"

namespace rugosim {

// [x0, x1) × [y0, y1) in GL window coordinates, px: row 0 is the framebuffer's first row, which
// holds the image's top row (frames are drawn upside down).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x1 <= x0 || y1 <= y0; }
  std::int64_t area() const { return empty() ? 0 : std::int64_t{x1 - x0} * std::int64_t{y1 - y0}; }
  friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

// The smallest rectangle holding both (an empty one holds nothing).
PixelRect bounding_rect(const PixelRect& a, const PixelRect& b);
bool rects_overlap(const PixelRect& a, const PixelRect& b);

// The window pixels that anything inside `body_box` (body frame, m) can touch once placed by
// `placement` and seen by `camera`, grown by `margin_px` for the GPU's float arithmetic and
// clipped to the frame; empty when it is all outside.
PixelRect window_rect(const Aabb& body_box, const Transform2& placement, const Camera& camera,
                      int margin_px);

// A few rectangles that together hold every one of `rects` (empties dropped). Two are merged
// into their bounding rectangle when that costs no more to draw than both apart, counting
// `pass_cost` pixels for each extra pass; then, while more than `max_count` remain, the pair
// whose bounding rectangle adds the least area. The result does not depend on anything but
// the input's order.
std::vector<PixelRect> merge_rects(std::vector<PixelRect> rects, std::int64_t pass_cost,
                                   std::size_t max_count);

}  // namespace rugosim
