#include "engine/core/transform.h"

#include <numbers>

#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

TEST(Transform2, RotatesThenTranslates) {
  const Transform2 x(std::numbers::pi / 2, Vec2(1, 2));
  const Vec2 p = x.apply(Vec2(1, 0));
  EXPECT_NEAR(p.x(), 1.0, 1e-15);
  EXPECT_NEAR(p.y(), 3.0, 1e-15);
  EXPECT_NEAR((x.rotate(Vec2(0, 1)) - Vec2(-1, 0)).norm(), 0.0, 1e-15);
}

TEST(Transform2, InverseAndCompositionAgreeWithApplyingInTurn) {
  Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Transform2 a(rng.uniform(-10, 10), Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5)));
    const Transform2 b(rng.uniform(-10, 10), Vec2(rng.uniform(-5, 5), rng.uniform(-5, 5)));
    const Vec2 p(rng.uniform(-3, 3), rng.uniform(-3, 3));
    EXPECT_LE(((a * b).apply(p) - a.apply(b.apply(p))).norm(), 1e-13);
    EXPECT_LE((a.inverse().apply(a.apply(p)) - p).norm(), 1e-13);
    EXPECT_LE((a.apply_inverse(a.apply(p)) - p).norm(), 1e-13);
    EXPECT_LE((a.rotation() * p - a.rotate(p)).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace rugosim
