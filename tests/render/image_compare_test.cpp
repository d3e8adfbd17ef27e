#include "render/snapshot/image_compare.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

Image random_frame(int width, int height, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Image image(width, height);
  for (auto& byte : image.rgba)
    byte = static_cast<std::uint8_t>(rng());
  return image;
}

// Makes pixel (x, y) of `actual` the golden one in R, G and B except channel `c`, which differs
// by exactly `delta`: up or down from the golden value, whichever fits in 0..255, and when
// neither does (a large delta from a middling value) the golden value is set to 0 first.
void set_diff(Image& golden, Image& actual, int x, int y, int c, int delta) {
  std::uint8_t* g = golden.pixel(x, y);
  std::uint8_t* a = actual.pixel(x, y);
  if (g[c] + delta > 255 && g[c] < delta) g[c] = 0;
  for (int i = 0; i < 3; ++i)
    a[i] = g[i];
  a[c] = static_cast<std::uint8_t>(g[c] + delta <= 255 ? g[c] + delta : g[c] - delta);
}

bool is_red(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255;
}

bool is_grey(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] == p[1] && p[1] == p[2] && p[0] >= 191 && p[3] == 255;
}

TEST(ImageCompare, IdenticalImagesAreIdenticalAndPass) {
  const Image golden = random_frame(320, 180, 1);
  const Image actual = golden;
  for (const bool exact : {false, true}) {
    CompareRule rule;
    rule.exact = exact;
    const CompareResult r = compare_images(golden, actual, rule);
    EXPECT_TRUE(r.identical);
    EXPECT_TRUE(r.passed);
    EXPECT_FALSE(r.size_mismatch);
    EXPECT_EQ(r.differing_pixels, 0U);
    EXPECT_EQ(r.failing_pixels, 0U);
    EXPECT_EQ(r.worst, 0);
    EXPECT_EQ(r.worst_x, -1);
    EXPECT_EQ(r.box_x0, -1);
    EXPECT_EQ(r.box_y1, -1);
    EXPECT_EQ(r.failing_share, 0.0);
    EXPECT_EQ(describe(r, rule), "identical");
  }
}

TEST(ImageCompare, OnePixelOffByOnePassesDefaultFailsExact) {
  Image golden = random_frame(320, 180, 2);
  Image actual = golden;
  set_diff(golden, actual, 100, 50, 1, 1);
  const CompareResult r = compare_images(golden, actual, CompareRule{});
  EXPECT_FALSE(r.identical);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.differing_pixels, 1U);
  EXPECT_EQ(r.failing_pixels, 0U);
  EXPECT_EQ(r.worst, 1);
  EXPECT_EQ(r.worst_x, 100);
  EXPECT_EQ(r.worst_y, 50);
  EXPECT_EQ(r.box_x0, -1);  // nothing fails, so no box

  CompareRule exact;
  exact.exact = true;
  const CompareResult e = compare_images(golden, actual, exact);
  EXPECT_FALSE(e.identical);
  EXPECT_FALSE(e.passed);
  EXPECT_EQ(e.differing_pixels, 1U);
  EXPECT_EQ(e.failing_pixels, 0U);
  // Under an exact rule the box bounds the differing pixels.
  EXPECT_EQ(e.box_x0, 100);
  EXPECT_EQ(e.box_y0, 50);
  EXPECT_EQ(e.box_x1, 100);
  EXPECT_EQ(e.box_y1, 50);
}

TEST(ImageCompare, OnePixelOffBy200PassesWithinShareFailsWithZeroShare) {
  Image golden = random_frame(320, 180, 3);
  Image actual = golden;
  set_diff(golden, actual, 7, 170, 0, 200);
  // The default max_share allows 0.1 % of 57 600 pixels, 57.6 of them.
  const CompareResult r = compare_images(golden, actual, CompareRule{});
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.differing_pixels, 1U);
  EXPECT_EQ(r.failing_pixels, 1U);
  EXPECT_EQ(r.worst, 200);
  EXPECT_DOUBLE_EQ(r.failing_share, 1.0 / 57600.0);

  CompareRule strict;
  strict.max_share = 0.0;
  const CompareResult s = compare_images(golden, actual, strict);
  EXPECT_FALSE(s.passed);
  EXPECT_EQ(s.box_x0, 7);
  EXPECT_EQ(s.box_y0, 170);
  EXPECT_EQ(s.box_x1, 7);
  EXPECT_EQ(s.box_y1, 170);
  EXPECT_EQ(s.worst_x, 7);
  EXPECT_EQ(s.worst_y, 170);
}

TEST(ImageCompare, ShareLimitIsInclusive) {
  // 57 failing pixels are within 57.6, 58 are not.
  Image golden = random_frame(320, 180, 4);
  Image actual = golden;
  for (int i = 0; i < 57; ++i)
    set_diff(golden, actual, i, 0, 2, 100);
  EXPECT_TRUE(compare_images(golden, actual, CompareRule{}).passed);
  set_diff(golden, actual, 57, 0, 2, 100);
  EXPECT_FALSE(compare_images(golden, actual, CompareRule{}).passed);
}

TEST(ImageCompare, ChangedBlockFailsWithItsBoxAndWorstPixel) {
  Image golden = random_frame(320, 180, 5);
  Image actual = golden;
  const int bx = 130, by = 60, size = 20;
  for (int y = by; y < by + size; ++y) {
    for (int x = bx; x < bx + size; ++x)
      set_diff(golden, actual, x, y, (x + y) % 3, 40);
  }
  // Two pixels share the largest difference: the first in row-major order is reported.
  set_diff(golden, actual, bx + 3, by + 11, 1, 90);
  set_diff(golden, actual, bx + 15, by + 4, 1, 90);
  const CompareResult r = compare_images(golden, actual, CompareRule{});
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.differing_pixels, 400U);
  EXPECT_EQ(r.failing_pixels, 400U);
  EXPECT_EQ(r.worst, 90);
  EXPECT_EQ(r.worst_x, bx + 15);
  EXPECT_EQ(r.worst_y, by + 4);
  EXPECT_EQ(r.box_x0, bx);
  EXPECT_EQ(r.box_y0, by);
  EXPECT_EQ(r.box_x1, bx + size - 1);
  EXPECT_EQ(r.box_y1, by + size - 1);
  EXPECT_DOUBLE_EQ(r.failing_share, 400.0 / 57600.0);
}

TEST(ImageCompare, DifferenceEqualToThresholdIsNotFailing) {
  for (const int threshold : {0, 1, 16, 200, 254}) {
    CompareRule rule;
    rule.threshold = threshold;
    rule.max_share = 0.0;
    Image golden = random_frame(64, 48, 6);
    Image at = golden;
    set_diff(golden, at, 10, 20, 2, threshold);
    const CompareResult r_at = compare_images(golden, at, rule);
    EXPECT_EQ(r_at.failing_pixels, 0U) << threshold;
    EXPECT_EQ(r_at.worst, threshold) << threshold;
    EXPECT_TRUE(r_at.passed) << threshold;
    Image above = golden;
    set_diff(golden, above, 10, 20, 2, threshold + 1);
    const CompareResult r_above = compare_images(golden, above, rule);
    EXPECT_EQ(r_above.failing_pixels, 1U) << threshold;
    EXPECT_EQ(r_above.worst, threshold + 1) << threshold;
    EXPECT_FALSE(r_above.passed) << threshold;
  }
}

// Frames of a transparent background carry alpha: it is compared like the colours.
TEST(ImageCompare, AlphaDifferencesCountLikeColours) {
  const Image golden = random_frame(64, 48, 7);
  Image actual = golden;
  std::uint8_t* p = actual.pixel(10, 20);
  p[3] = static_cast<std::uint8_t>(p[3] >= 128 ? p[3] - 100 : p[3] + 100);
  CompareRule exact;
  exact.exact = true;
  const CompareResult r = compare_images(golden, actual, exact);
  EXPECT_FALSE(r.identical);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.differing_pixels, 1U);
  EXPECT_EQ(r.worst, 100);
}

TEST(ImageCompare, SizeMismatchFailsAndDescribeNamesBothSizes) {
  const Image golden = random_frame(320, 180, 8);
  const Image actual = random_frame(321, 179, 8);
  const CompareResult r = compare_images(golden, actual, CompareRule{});
  EXPECT_TRUE(r.size_mismatch);
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.identical);
  const std::string text = describe(r, CompareRule{});
  EXPECT_NE(text.find("320×180"), std::string::npos) << text;
  EXPECT_NE(text.find("321×179"), std::string::npos) << text;
}

TEST(ImageCompare, BadRulesAndMalformedImagesThrow) {
  const Image image = random_frame(8, 8, 9);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const int threshold : {-1, 256, 1000}) {
    CompareRule rule;
    rule.threshold = threshold;
    EXPECT_THROW(compare_images(image, image, rule), std::invalid_argument) << threshold;
    EXPECT_THROW(difference_image(image, image, rule), std::invalid_argument) << threshold;
  }
  for (const double share : {-0.001, 1.001, nan, inf, -inf}) {
    CompareRule rule;
    rule.max_share = share;
    EXPECT_THROW(compare_images(image, image, rule), std::invalid_argument) << share;
  }
  for (const int threshold : {0, 255}) {
    CompareRule rule;
    rule.threshold = threshold;
    EXPECT_NO_THROW(compare_images(image, image, rule));
  }
  for (const double share : {0.0, 1.0}) {
    CompareRule rule;
    rule.max_share = share;
    EXPECT_NO_THROW(compare_images(image, image, rule));
  }
  Image malformed = image;
  malformed.rgba.pop_back();
  EXPECT_THROW(compare_images(image, malformed, CompareRule{}), std::invalid_argument);
  EXPECT_THROW(compare_images(malformed, image, CompareRule{}), std::invalid_argument);
}

TEST(ImageCompare, DifferenceImageGreysUnchangedAndMarksChanged) {
  Image golden = random_frame(96, 64, 10);
  Image actual = golden;
  set_diff(golden, actual, 40, 30, 0, 200);  // failing
  set_diff(golden, actual, 5, 5, 1, 3);      // within the threshold
  const Image diff = difference_image(golden, actual, CompareRule{});
  ASSERT_EQ(diff.width, 96);
  ASSERT_EQ(diff.height, 64);
  EXPECT_TRUE(is_red(diff, 40, 30));
  const std::uint8_t* orange = diff.pixel(5, 5);
  EXPECT_EQ(orange[0], 0xff);
  EXPECT_EQ(orange[1], 0xa5);
  EXPECT_EQ(orange[2], 0x00);
  // The rectangle's lines are 3 px outside the lone failing pixel: x, y in 37 and 43.
  for (const int t : {37, 40, 43}) {
    EXPECT_TRUE(is_red(diff, t, 27)) << t;
    EXPECT_TRUE(is_red(diff, t, 33)) << t;
    EXPECT_TRUE(is_red(diff, 37, t - 10)) << t;
    EXPECT_TRUE(is_red(diff, 43, t - 10)) << t;
  }
  // Between the rectangle and the pixel nothing is red.
  for (const int d : {1, 2}) {
    EXPECT_FALSE(is_red(diff, 40 - d, 30));
    EXPECT_FALSE(is_red(diff, 40 + d, 30));
    EXPECT_FALSE(is_red(diff, 40, 30 - d));
    EXPECT_FALSE(is_red(diff, 40, 30 + d));
  }
  // Everything else is light grey.
  int red = 0;
  for (int y = 0; y < diff.height; ++y) {
    for (int x = 0; x < diff.width; ++x) {
      if (is_red(diff, x, y)) {
        ++red;
        continue;
      }
      if (x == 5 && y == 5) continue;
      EXPECT_TRUE(is_grey(diff, x, y)) << x << ", " << y;
    }
  }
  EXPECT_EQ(red, 1 + 4 * 6);  // the pixel and a 7 × 7 outline
}

TEST(ImageCompare, DifferenceImageGreyFollowsLuma) {
  Image golden(3, 1);
  const std::uint8_t colours[3][3] = {{0, 0, 0}, {255, 255, 255}, {0, 255, 0}};
  for (int x = 0; x < 3; ++x) {
    for (int c = 0; c < 3; ++c)
      golden.pixel(x, 0)[c] = colours[x][c];
  }
  const Image diff = difference_image(golden, golden, CompareRule{});
  EXPECT_EQ(diff.pixel(0, 0)[0], 191);  // black, 75 % towards white
  EXPECT_EQ(diff.pixel(1, 0)[0], 255);
  EXPECT_GT(diff.pixel(2, 0)[0], 191);  // green is bright
  EXPECT_LT(diff.pixel(2, 0)[0], 255);
}

TEST(ImageCompare, DifferenceImageClipsTheRectangleAtTheEdge) {
  Image golden = random_frame(32, 32, 11);
  Image actual = golden;
  set_diff(golden, actual, 1, 0, 0, 100);
  const Image diff = difference_image(golden, actual, CompareRule{});
  EXPECT_TRUE(is_red(diff, 1, 0));
  // Left and top sides fall outside; the right side (x = 4) and bottom side (y = 3) remain.
  for (int y = 0; y <= 3; ++y)
    EXPECT_TRUE(is_red(diff, 4, y)) << y;
  for (int x = 0; x <= 4; ++x)
    EXPECT_TRUE(is_red(diff, x, 3)) << x;
  EXPECT_FALSE(is_red(diff, 0, 0));
  EXPECT_FALSE(is_red(diff, 2, 1));
}

TEST(ImageCompare, DifferenceImageUnderExactRuleMarksEveryDifferenceRed) {
  Image golden = random_frame(32, 32, 12);
  Image actual = golden;
  set_diff(golden, actual, 16, 16, 2, 1);
  CompareRule exact;
  exact.exact = true;
  const Image diff = difference_image(golden, actual, exact);
  EXPECT_TRUE(is_red(diff, 16, 16));
  EXPECT_TRUE(is_red(diff, 13, 13));
  EXPECT_TRUE(is_red(diff, 19, 16));
}

TEST(ImageCompare, DifferenceImageOnSizeMismatchIsTheActualsSizeAllMarked) {
  const Image golden = random_frame(20, 10, 13);
  const Image actual = random_frame(12, 7, 14);
  const Image diff = difference_image(golden, actual, CompareRule{});
  ASSERT_EQ(diff.width, 12);
  ASSERT_EQ(diff.height, 7);
  for (int y = 0; y < diff.height; ++y) {
    for (int x = 0; x < diff.width; ++x)
      EXPECT_TRUE(is_red(diff, x, y)) << x << ", " << y;
  }
}

TEST(ImageCompare, DescribeGivesTheNumbers) {
  Image golden = random_frame(320, 180, 15);
  Image actual = golden;
  const int bx = 118, by = 40;
  for (int y = by; y <= 52; ++y) {
    for (int x = bx; x <= 131; ++x) {
      if ((x + y) % 7 == 0) set_diff(golden, actual, x, y, 0, 30);
    }
  }
  set_diff(golden, actual, 118, 40, 1, 30);  // the top-left corner of the box
  set_diff(golden, actual, 131, 52, 1, 30);  // and the bottom-right one
  set_diff(golden, actual, 120, 44, 2, 87);
  set_diff(golden, actual, 300, 170, 1, 5);  // within the threshold
  const CompareRule rule;
  const CompareResult r = compare_images(golden, actual, rule);
  ASSERT_EQ(r.worst, 87);
  ASSERT_EQ(r.box_x0, 118);
  ASSERT_EQ(r.box_y1, 52);
  const std::string text = describe(r, rule);
  const std::string count = std::to_string(r.failing_pixels) + " pixels differ (";
  EXPECT_EQ(text.rfind(count, 0), 0U) << text;
  for (const char* part : {"rule: threshold 16, max 0.1%", "worst 87 at (120, 44)",
                           "in the box (118, 40)–(131, 52)", "1 more within the threshold"}) {
    EXPECT_NE(text.find(part), std::string::npos) << part << " in " << text;
  }

  // 12 of 57 600 pixels: 0.0208 %.
  Image twelve = golden;
  for (int i = 0; i < 12; ++i)
    set_diff(golden, twelve, 10 + i, 10, 0, 50);
  const std::string twelve_text = describe(compare_images(golden, twelve, rule), rule);
  EXPECT_EQ(twelve_text.rfind("12 pixels differ (0.0208%,", 0), 0U) << twelve_text;

  CompareRule exact;
  exact.exact = true;
  Image one = golden;
  set_diff(golden, one, 3, 4, 0, 1);
  const std::string exact_text = describe(compare_images(golden, one, exact), exact);
  EXPECT_EQ(exact_text,
            "1 pixel differs (0.00174%, rule: exact), worst 1 at (3, 4), in the box (3, 4)–(3, 4)");
}

}  // namespace
}  // namespace rugosim
