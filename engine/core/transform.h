// Rigid placement in the plane: a rotation by `angle` followed by a translation. Maps a body
// frame to the world (or one body's frame to another's).
#pragma once

#include <cmath>

#include "engine/core/types.h"

namespace rugosim {

class Transform2 {
 public:
  Transform2() = default;
  Transform2(double angle, const Vec2& translation)
      : cos_(std::cos(angle)), sin_(std::sin(angle)), translation_(translation) {}

  static Transform2 identity() { return Transform2(); }

  // R·p + t, for points.
  Vec2 apply(const Vec2& p) const { return rotate(p) + translation_; }
  // R·v, for directions and offsets.
  Vec2 rotate(const Vec2& v) const {
    return Vec2(cos_ * v.x() - sin_ * v.y(), sin_ * v.x() + cos_ * v.y());
  }
  // Rᵀ·(p − t): the inverse placement applied to a point.
  Vec2 apply_inverse(const Vec2& p) const { return rotate_inverse(p - translation_); }
  Vec2 rotate_inverse(const Vec2& v) const {
    return Vec2(cos_ * v.x() + sin_ * v.y(), -sin_ * v.x() + cos_ * v.y());
  }

  Transform2 inverse() const {
    Transform2 inv;
    inv.cos_ = cos_;
    inv.sin_ = -sin_;
    inv.translation_ = -rotate_inverse(translation_);
    return inv;
  }
  // (this ∘ other)(p) = this(other(p)).
  Transform2 operator*(const Transform2& other) const {
    Transform2 out;
    out.cos_ = cos_ * other.cos_ - sin_ * other.sin_;
    out.sin_ = sin_ * other.cos_ + cos_ * other.sin_;
    out.translation_ = apply(other.translation_);
    return out;
  }

  Mat2 rotation() const { return (Mat2() << cos_, -sin_, sin_, cos_).finished(); }
  const Vec2& translation() const { return translation_; }
  double cos_angle() const { return cos_; }
  double sin_angle() const { return sin_; }

 private:
  double cos_ = 1.0;
  double sin_ = 0.0;
  Vec2 translation_ = Vec2::Zero();
};

}  // namespace rugosim
