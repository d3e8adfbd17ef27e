// Dirty rectangles (dirty_rects.h): a placed box's window rectangle holds every pixel that a
// point of the box lands in (brute force over seeded random boxes, placements and cameras),
// and merged rectangles still hold every input, within the count asked for.
#include "render/draw/dirty_rects.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

bool holds(const PixelRect& outer, const PixelRect& inner) {
  return inner.empty() || (outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && inner.x1 <= outer.x1 &&
                           inner.y1 <= outer.y1);
}

Camera camera(double height_m, int w, int h, Vec2 center) {
  Camera c;
  c.center = center;
  c.height = height_m;
  c.width_px = w;
  c.height_px = h;
  return c;
}

TEST(DirtyRects, WindowRectHoldsEveryPixelTheBoxLandsIn) {
  std::mt19937_64 random(20261201);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Camera cam = camera(0.5 + 4.0 * unit(random), 64 + static_cast<int>(400 * unit(random)),
                              48 + static_cast<int>(300 * unit(random)),
                              Vec2(unit(random) - 0.5, unit(random) - 0.5));
    Aabb box;
    box.extend(Vec2(unit(random) - 0.5, unit(random) - 0.5));
    box.extend(Vec2(unit(random) - 0.5, unit(random) - 0.5));
    const Transform2 place(6.3 * unit(random), Vec2(2.0 * unit(random) - 1.0, unit(random) - 0.5));
    const PixelRect rect = window_rect(box, place, cam, 0);
    for (int s = 0; s < 200; ++s) {
      const Vec2 local(box.min.x() + unit(random) * box.extent().x(),
                       box.min.y() + unit(random) * box.extent().y());
      const Vec2 px = cam.to_pixels(place.apply(local));
      const double x = 0.5 * cam.width_px + px.x();
      const double y = 0.5 * cam.height_px - px.y();
      if (x < 0 || y < 0 || x >= cam.width_px || y >= cam.height_px) continue;  // off frame
      const int ix = static_cast<int>(std::floor(x));
      const int iy = static_cast<int>(std::floor(y));
      ASSERT_TRUE(ix >= rect.x0 && ix < rect.x1 && iy >= rect.y0 && iy < rect.y1)
          << "trial " << trial << ": pixel (" << ix << ", " << iy << ") outside [" << rect.x0
          << ", " << rect.x1 << ") x [" << rect.y0 << ", " << rect.y1 << ")";
    }
  }
}

TEST(DirtyRects, WindowRectIsClippedToTheFrameAndGrowsByTheMargin) {
  const Camera cam = camera(1.0, 100, 100, Vec2::Zero());  // 0.01 m per pixel, y down in rows
  Aabb box;
  box.extend(Vec2(-0.1, -0.1));
  box.extend(Vec2(0.1, 0.1));
  const PixelRect centred = window_rect(box, Transform2(), cam, 0);
  EXPECT_LE(centred.x0, 40);
  EXPECT_GE(centred.x1, 60);
  EXPECT_LE(centred.x1, 62);
  const PixelRect grown = window_rect(box, Transform2(), cam, 3);
  EXPECT_EQ(grown.x0, centred.x0 - 3);
  EXPECT_EQ(grown.y1, centred.y1 + 3);
  // y up in the world is down in window rows: a box above the centre has small rows.
  const PixelRect high = window_rect(box, Transform2(0.0, Vec2(0.0, 0.3)), cam, 0);
  EXPECT_LT(high.y1, 50);
  // Partly outside: clipped; wholly outside: empty.
  const PixelRect edge = window_rect(box, Transform2(0.0, Vec2(0.5, 0.0)), cam, 0);
  EXPECT_EQ(edge.x1, 100);
  EXPECT_TRUE(window_rect(box, Transform2(0.0, Vec2(5.0, 0.0)), cam, 0).empty());
  EXPECT_TRUE(window_rect(Aabb{}, Transform2(), cam, 0).empty());
  // A body placed nowhere (NaN) may be anywhere: the whole frame.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(window_rect(box, Transform2(0.0, Vec2(nan, 0.0)), cam, 0), (PixelRect{0, 0, 100, 100}));
  EXPECT_EQ(window_rect(box, Transform2(nan, Vec2::Zero()), cam, 0), (PixelRect{0, 0, 100, 100}));
  // Huge coordinates stay in range.
  Aabb far;
  far.extend(Vec2(-1e300, -1e300));
  far.extend(Vec2(1e300, 1e300));
  EXPECT_EQ(window_rect(far, Transform2(), cam, 0), (PixelRect{0, 0, 100, 100}));
}

TEST(DirtyRects, MergedRectanglesHoldEveryInputWithinTheCount) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<int> coordinate(0, 1000);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<PixelRect> rects;
    const int n = 1 + trial % 40;
    for (int i = 0; i < n; ++i) {
      const int x = coordinate(random), y = coordinate(random);
      rects.push_back({x, y, x + coordinate(random) / 8, y + coordinate(random) / 8});
    }
    for (const std::size_t max_count : {std::size_t{1}, std::size_t{3}, std::size_t{6}}) {
      const std::vector<PixelRect> merged = merge_rects(rects, 128 * 128, max_count);
      ASSERT_LE(merged.size(), max_count);
      for (const PixelRect& r : rects) {
        bool inside = false;
        for (const PixelRect& m : merged)
          inside = inside || holds(m, r);
        ASSERT_TRUE(inside) << "trial " << trial;
      }
      for (const PixelRect& m : merged)
        EXPECT_FALSE(m.empty());
      EXPECT_EQ(merge_rects(rects, 128 * 128, max_count), merged);  // deterministic
    }
  }
}

TEST(DirtyRects, MergesOverlappingAndNearbyRectanglesButKeepsDistantOnesApart) {
  // A body's rectangles before and after a small move become one.
  EXPECT_EQ(merge_rects({{10, 10, 50, 50}, {12, 11, 52, 51}}, 0, 8),
            (std::vector<PixelRect>{{10, 10, 52, 51}}));
  // Two bodies at opposite corners of a large frame stay two passes.
  EXPECT_EQ(merge_rects({{0, 0, 40, 40}, {900, 900, 940, 940}}, 128 * 128, 8).size(), 2u);
  // With one pass allowed they become their bounding rectangle.
  EXPECT_EQ(merge_rects({{0, 0, 40, 40}, {900, 900, 940, 940}}, 128 * 128, 1),
            (std::vector<PixelRect>{{0, 0, 940, 940}}));
  // Empty rectangles vanish.
  EXPECT_TRUE(merge_rects({{5, 5, 5, 9}, {3, 3, 1, 1}}, 0, 4).empty());
}

}  // namespace
}  // namespace rugosim
