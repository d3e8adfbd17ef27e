#include "render/draw/camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rugosim {

Camera fit_camera(const Aabb& bounds, int width_px, int height_px, double margin) {
  if (bounds.empty() || !std::isfinite(bounds.min.x()) || !std::isfinite(bounds.min.y()) ||
      !std::isfinite(bounds.max.x()) || !std::isfinite(bounds.max.y())) {
    throw std::invalid_argument("camera: nothing finite to frame");
  }
  Camera camera;
  camera.width_px = width_px;
  camera.height_px = height_px;
  camera.center = bounds.center();
  const Vec2 extent = bounds.extent();
  const double aspect = static_cast<double>(width_px) / height_px;
  // The height that fits both the extent's height and its width at this aspect; a point-like
  // scene still gets a finite view.
  double height = std::max(extent.y(), extent.x() / aspect);
  if (!(height > 0.0)) height = 1.0;
  camera.height = height * (1.0 + 2.0 * margin);
  return camera;
}

}  // namespace rugosim
