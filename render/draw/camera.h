// What part of the world a frame shows: a centre and a visible height; the width follows from
// the frame's aspect. Fixed for a whole clip, so the rugosity detail is generated once at its
// pixel size.
#pragma once

#include <span>

#include "engine/core/aabb.h"
#include "engine/core/types.h"

namespace rugosim {

struct Camera {
  Vec2 center = Vec2::Zero();  // m
  double height = 1.0;         // m of world from the bottom of the frame to the top
  int width_px = 1;
  int height_px = 1;

  double pixel_size() const { return height / height_px; }  // m per pixel
  double width() const { return pixel_size() * width_px; }  // m
  // World point → pixels from the frame's centre, y up.
  Vec2 to_pixels(const Vec2& world) const { return (world - center) / pixel_size(); }
};

// The camera that shows all of `bounds` with `margin` (a fraction of the larger side) around
// it, centred. Throws std::invalid_argument for empty or non-finite bounds.
Camera fit_camera(const Aabb& bounds, int width_px, int height_px, double margin = 0.06);

}  // namespace rugosim
