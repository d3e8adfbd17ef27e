#include "render/draw/dirty_rects.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rugosim {

PixelRect bounding_rect(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

bool rects_overlap(const PixelRect& a, const PixelRect& b) {
  return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

PixelRect window_rect(const Aabb& body_box, const Transform2& placement, const Camera& camera,
                      int margin_px) {
  const PixelRect frame{0, 0, camera.width_px, camera.height_px};
  if (body_box.empty()) return {};
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x;
  double lo_y = lo_x, hi_y = -lo_x;
  const Vec2 corners[] = {body_box.min,
                          {body_box.max.x(), body_box.min.y()},
                          body_box.max,
                          {body_box.min.x(), body_box.max.y()}};
  for (const Vec2& corner : corners) {
    // The mapping of SceneRenderer::upload_transforms, in window pixels: y grows downwards.
    const Vec2 px = camera.to_pixels(placement.apply(corner));
    const double x = 0.5 * camera.width_px + px.x();
    const double y = 0.5 * camera.height_px - px.y();
    lo_x = std::min(lo_x, x);
    hi_x = std::max(hi_x, x);
    lo_y = std::min(lo_y, y);
    hi_y = std::max(hi_y, y);
  }
  // NaN compares false everywhere: such a box may be anywhere, so it is the whole frame.
  if (!(lo_x <= hi_x && lo_y <= hi_y)) return frame;
  auto clip = [](double v, int limit) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(limit)));
  };
  PixelRect r{clip(std::floor(lo_x) - margin_px, frame.x1),
              clip(std::floor(lo_y) - margin_px, frame.y1),
              clip(std::ceil(hi_x) + margin_px + 1, frame.x1),
              clip(std::ceil(hi_y) + margin_px + 1, frame.y1)};
  return r.empty() ? PixelRect{} : r;
}

std::vector<PixelRect> merge_rects(std::vector<PixelRect> rects, std::int64_t pass_cost,
                                   std::size_t max_count) {
  std::erase_if(rects, [](const PixelRect& r) { return r.empty(); });
  // Merge while some pair is as cheap together as apart. Each merge removes a rectangle, so
  // this ends after at most as many rounds as there are rectangles.
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < rects.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < rects.size(); ++j) {
        const PixelRect both = bounding_rect(rects[i], rects[j]);
        if (both.area() <= rects[i].area() + rects[j].area() + pass_cost) {
          rects[i] = both;
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
          break;
        }
      }
    }
  }
  max_count = std::max<std::size_t>(max_count, 1);
  while (rects.size() > max_count) {
    std::size_t best_i = 0, best_j = 1;
    std::int64_t best_growth = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < rects.size(); ++i) {
      for (std::size_t j = i + 1; j < rects.size(); ++j) {
        const std::int64_t growth =
            bounding_rect(rects[i], rects[j]).area() - rects[i].area() - rects[j].area();
        if (growth < best_growth) {
          best_growth = growth;
          best_i = i;
          best_j = j;
        }
      }
    }
    rects[best_i] = bounding_rect(rects[best_i], rects[best_j]);
    rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(best_j));
  }
  return rects;
}

}  // namespace rugosim
