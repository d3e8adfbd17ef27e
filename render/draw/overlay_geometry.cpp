#include "render/draw/overlay_geometry.h"

#include <algorithm>
#include <cmath>

namespace rugosim {
namespace {

const Rgba kCollision = *parse_hex_color("#d1345b");
const Rgba kContact = *parse_hex_color("#1f7a8c");
const Rgba kVelocity = *parse_hex_color("#2b2d42");

constexpr double kVelocitySeconds = 0.25;  // an arrow shows where the body would be this later
constexpr double kLongestArrowPx = 240.0;

}  // namespace

OverlayBuilder::OverlayBuilder(const Camera& camera, float fringe, float scale, bool flip_y)
    : camera_(camera), fringe_(fringe), scale_(scale), y_sign_(flip_y ? -1.f : 1.f) {}

void OverlayBuilder::corner(const Vec2& px, float along, float across, const Rgba& colour,
                            float half, float disc) {
  const auto& c = colour.channels;
  vertices_.push_back(OverlayVertex{static_cast<float>(2.0 * px.x() / camera_.width_px),
                                    y_sign_ * static_cast<float>(2.0 * px.y() / camera_.height_px),
                                    along, across, c[0], c[1], c[2], c[3], half, disc});
}

void OverlayBuilder::line(const Vec2& from_px, const Vec2& to_px, float width_px,
                          const Rgba& colour) {
  const Vec2 d = to_px - from_px;
  const double length = d.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return;
  const float half = 0.5f * width_px * scale_;
  shapes_.push_back({false, from_px, to_px, half, colour});
  const float reach = half + fringe_;
  const Vec2 u = d / length;
  const Vec2 n(-u.y(), u.x());
  // Round-ish caps: the quad runs `reach` past both ends.
  const Vec2 a = from_px - reach * u;
  const Vec2 b = to_px + reach * u;
  const auto len = static_cast<float>(length);
  const Vec2 quad[4] = {a - reach * n, a + reach * n, b - reach * n, b + reach * n};
  const float along[4] = {-reach, -reach, len + reach, len + reach};
  const float across[4] = {-reach, reach, -reach, reach};
  for (int i : {0, 1, 2, 2, 1, 3})
    corner(quad[i], along[i], across[i], colour, half, 0.f);
}

void OverlayBuilder::disc(const Vec2& centre_px, float radius_px, const Rgba& colour) {
  const float radius = radius_px * scale_;
  shapes_.push_back({true, centre_px, centre_px, radius, colour});
  const float reach = radius + fringe_;
  const float sx[4] = {-reach, reach, -reach, reach};
  const float sy[4] = {-reach, -reach, reach, reach};
  for (int i : {0, 1, 2, 2, 1, 3}) {
    corner(centre_px + Vec2(sx[i], sy[i]), sx[i], sy[i], colour, radius, 1.f);
  }
}

void OverlayBuilder::arrow(const Vec2& from_px, const Vec2& to_px, float width_px,
                           const Rgba& colour) {
  line(from_px, to_px, width_px, colour);
  const Vec2 d = to_px - from_px;
  const double length = d.norm();
  if (!(length > 0.0)) return;
  const Vec2 back = -d / length * std::min(10.0 * double{scale_}, 0.4 * length);
  const Vec2 side(-back.y() * 0.5, back.x() * 0.5);
  line(to_px, to_px + back + side, width_px, colour);
  line(to_px, to_px + back - side, width_px, colour);
}

void OverlayBuilder::add_frame(const FrameSnapshot& frame, const std::vector<bool>& fixed,
                               const Overlays& overlays) {
  if (overlays.contacts) {
    // Resting contacts first, so that collisions stay visible on top of them.
    for (const bool collisions : {false, true}) {
      for (const ContactEvent& e : frame.events) {
        if ((e.kind == EventKind::kCollision) != collisions) continue;
        const Rgba& colour = collisions ? kCollision : kContact;
        const Vec2 at = camera_.to_pixels(e.point);
        const Vec2 tangent(-e.normal.y(), e.normal.x());
        // The impulse on A; when A is fixed, the one on B (−J), so strokes show how moving
        // bodies are pushed.
        const double sign = e.body_a < fixed.size() && fixed[e.body_a] ? -1.0 : 1.0;
        const Vec2 impulse = sign * (e.jn * e.normal + e.jt * tangent);
        const double size = impulse.norm();
        if (size > 0.0) {
          const Vec2 direction(impulse.x() / size, impulse.y() / size);
          line(at, at + (collisions ? 22.0 : 12.0) * double{scale_} * direction, 1.5f, colour);
        }
        disc(at, collisions ? 3.5f : 2.2f, colour);
      }
    }
  }
  if (overlays.velocity) {
    for (std::size_t i = 0; i < frame.bodies.size(); ++i) {
      const BodyPose& pose = frame.bodies[i];
      if ((i < fixed.size() && fixed[i]) || pose.asleep) continue;
      const Vec2 from = camera_.to_pixels(pose.placement.translation());
      Vec2 reach = pose.velocity * (kVelocitySeconds / camera_.pixel_size());
      const double length = reach.norm();
      if (!(length >= 2.0) || !std::isfinite(length)) continue;
      const double longest = kLongestArrowPx * double{scale_};
      if (length > longest) reach *= longest / length;
      disc(from, 2.5f, kVelocity);
      arrow(from, from + reach, 2.0f, kVelocity);
    }
  }
}

}  // namespace rugosim
