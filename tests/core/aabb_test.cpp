#include "engine/core/aabb.h"

#include <gtest/gtest.h>

namespace rugosim {
namespace {

TEST(Aabb, StartsEmptyAndGrowsToContainPoints) {
  Aabb box;
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.diagonal(), 0.0);
  box.extend(Vec2(1, 2));
  EXPECT_FALSE(box.empty());
  box.extend(Vec2(-1, 0));
  EXPECT_EQ(box.min, Vec2(-1, 0));
  EXPECT_EQ(box.max, Vec2(1, 2));
  EXPECT_TRUE(box.contains(Vec2(0, 1)));
  EXPECT_FALSE(box.contains(Vec2(1.5, 1)));
  EXPECT_TRUE(box.contains(Vec2(1.5, 1), 0.5));
  EXPECT_DOUBLE_EQ(box.diagonal(), std::sqrt(8.0));
}

TEST(Aabb, OverlapIsSymmetricAndIncludesTouching) {
  Aabb a, b, c;
  a.extend(Vec2(0, 0));
  a.extend(Vec2(1, 1));
  b.extend(Vec2(1, 1));
  b.extend(Vec2(2, 2));
  c.extend(Vec2(1.01, 0));
  c.extend(Vec2(2, 0.5));
  EXPECT_TRUE(a.overlaps(b));
  EXPECT_TRUE(b.overlaps(a));
  EXPECT_FALSE(a.overlaps(c));
  EXPECT_FALSE(c.overlaps(a));
}

}  // namespace
}  // namespace rugosim
