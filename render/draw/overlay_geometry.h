// The overlays a user can ask for on top of the bodies (INTERFACE.md, render.overlays and
// --overlay): `contacts` (each impulse of the frame: a dot at the contact point and a stroke
// along the impulse's direction; collisions and resting contacts in two colours) and `velocity`
// (an arrow from each moving body's centre of mass along its velocity). Strokes show the impulse
// on a moving body: on A, or on B when A is fixed. `rugosity` colours the
// outlines themselves and is drawn by the renderer. Geometry is made on the CPU each frame, in
// normalised device coordinates, as quads whose vertices know their pixel offsets, so one
// shader anti-aliases lines and discs alike.
#pragma once

#include <array>
#include <vector>

#include "engine/dynamics/frame_snapshot.h"
#include "render/color.h"
#include "render/draw/camera.h"

namespace rugosim {

struct Overlays {
  bool rugosity = false;
  bool contacts = false;
  bool velocity = false;
  bool any() const { return rugosity || contacts || velocity; }
};

struct OverlayVertex {
  float x, y;           // normalised device coordinates
  float along, across;  // px from the line's start and centre line, or from the disc's centre
  float r, g, b, a;     // colour
  float half_width;     // px: half the line's width, or the disc's radius
  float disc;           // 1 for a disc, 0 for a line
};

// One overlay shape as drawn, for vector output: a line from `from` to `to` (square caps) or a
// disc at `from`, in px from the frame's centre, y up; sizes already scaled.
struct OverlayShape {
  bool disc = false;
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  double half_width = 0.0;  // px: half the line's width, or the disc's radius
  Rgba colour;
};

class OverlayBuilder {
 public:
  // `fringe` px of anti-aliasing ramp around every shape (0 with MSAA); `scale` multiplies
  // every size (1 at 720 lines). `flip_y` draws the frame upside down (rows top first).
  OverlayBuilder(const Camera& camera, float fringe, float scale, bool flip_y);

  void clear() {
    vertices_.clear();
    shapes_.clear();
  }
  void line(const Vec2& from_px, const Vec2& to_px, float width_px, const Rgba& colour);
  void disc(const Vec2& centre_px, float radius_px, const Rgba& colour);
  // A line with a two-stroke head at `to_px`.
  void arrow(const Vec2& from_px, const Vec2& to_px, float width_px, const Rgba& colour);

  // The contact and velocity overlays of one frame. `fixed[i]` tells fixed bodies apart.
  void add_frame(const FrameSnapshot& frame, const std::vector<bool>& fixed,
                 const Overlays& overlays);

  const std::vector<OverlayVertex>& vertices() const { return vertices_; }
  const std::vector<OverlayShape>& shapes() const { return shapes_; }

 private:
  void corner(const Vec2& px, float along, float across, const Rgba& colour, float half,
              float disc);

  Camera camera_;
  float fringe_;
  float scale_;
  float y_sign_;
  std::vector<OverlayVertex> vertices_;
  std::vector<OverlayShape> shapes_;
};

}  // namespace rugosim
