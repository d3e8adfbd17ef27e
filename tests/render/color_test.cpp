#include "render/color.h"

#include <gtest/gtest.h>

namespace rugosim {
namespace {

TEST(ParseHexColor, ReadsSixAndEightDigitForms) {
  const auto opaque = parse_hex_color("#f4f1ea");
  ASSERT_TRUE(opaque.has_value());
  EXPECT_FLOAT_EQ(opaque->channels[0], 244.f / 255.f);
  EXPECT_FLOAT_EQ(opaque->channels[1], 241.f / 255.f);
  EXPECT_FLOAT_EQ(opaque->channels[2], 234.f / 255.f);
  EXPECT_FLOAT_EQ(opaque->channels[3], 1.f);
  const auto translucent = parse_hex_color("#00FF0080");
  ASSERT_TRUE(translucent.has_value());
  EXPECT_FLOAT_EQ(translucent->channels[1], 1.f);
  EXPECT_FLOAT_EQ(translucent->channels[3], 128.f / 255.f);
}

TEST(ParseHexColor, RejectsMalformedText) {
  for (const char* bad : {"", "#", "f4f1ea", "#f4f1e", "#f4f1eag", "#12345678901", "#gggggg"}) {
    EXPECT_FALSE(parse_hex_color(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace rugosim
