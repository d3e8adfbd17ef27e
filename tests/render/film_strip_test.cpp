#include "render/sinks/film_strip.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

Image random_frame(int width, int height, std::mt19937& rng) {
  Image image(width, height);
  for (auto& byte : image.rgba)
    byte = static_cast<std::uint8_t>(rng());
  return image;
}

// Five frames in rows of two with label bands: every pixel is a frame's own, or background.
TEST(FilmStrip, GridPutsFramesInReadingOrderWithBandsAndGaps) {
  std::mt19937 rng(32);
  const int width = 4;
  const int height = 3;
  const StripGrid grid{2, 1, 2};
  const std::array<std::uint8_t, 4> background{9, 8, 7, 6};
  std::vector<Image> frames;
  for (int i = 0; i < 5; ++i)
    frames.push_back(random_frame(width, height, rng));
  const Image strip = compose_film_grid(frames, grid, background);
  ASSERT_EQ(strip.width, 2 * width + 1);
  ASSERT_EQ(strip.height, 3 * (height + 2) + 2 * 1);
  std::vector<int> owner(static_cast<std::size_t>(strip.width * strip.height), -1);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto [x0, y0] = grid_cell(grid, width, height, i, frames.size());
    EXPECT_EQ(x0, static_cast<int>(i % 2) * (width + 1));
    EXPECT_EQ(y0, static_cast<int>(i / 2) * (height + 2 + 1));
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        EXPECT_TRUE(std::equal(frames[i].pixel(x, y), frames[i].pixel(x, y) + 4,
                               strip.pixel(x0 + x, y0 + y)));
        owner[static_cast<std::size_t>((y0 + y) * strip.width + x0 + x)] = static_cast<int>(i);
      }
    }
  }
  for (int y = 0; y < strip.height; ++y) {
    for (int x = 0; x < strip.width; ++x) {
      if (owner[static_cast<std::size_t>(y * strip.width + x)] >= 0) continue;
      EXPECT_TRUE(std::equal(background.begin(), background.end(), strip.pixel(x, y)))
          << x << "," << y;
    }
  }
  // More columns than frames: one row.
  EXPECT_EQ(compose_film_grid(frames, StripGrid{9, 0, 0}, background).height, height);
  EXPECT_THROW(compose_film_grid(frames, StripGrid{-1, 0, 0}, background), std::invalid_argument);
  EXPECT_THROW(compose_film_grid(frames, StripGrid{2, 0, -3}, background), std::invalid_argument);
}

TEST(FilmStrip, FramesSideBySideWithGapsBetweenOnly) {
  std::mt19937 rng(31);
  const int width = 5;
  const int height = 3;
  const int gap = 2;
  const std::array<std::uint8_t, 4> colour{1, 2, 3, 4};
  const std::vector<Image> frames{random_frame(width, height, rng),
                                  random_frame(width, height, rng),
                                  random_frame(width, height, rng)};
  const Image strip = compose_film_strip(frames, gap, colour);
  ASSERT_EQ(strip.width, 3 * width + 2 * gap);
  ASSERT_EQ(strip.height, height);
  ASSERT_EQ(strip.rgba.size(), strip.stride() * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < strip.width; ++x) {
      const int slot = x / (width + gap);
      const int within = x % (width + gap);
      const std::uint8_t* actual = strip.pixel(x, y);
      const std::uint8_t* expected =
          within < width ? frames[static_cast<std::size_t>(slot)].pixel(within, y) : colour.data();
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(actual[c], expected[c]) << "(" << x << ", " << y << ") channel " << c;
      }
    }
  }
}

TEST(FilmStrip, NoGapAndOneFrame) {
  std::mt19937 rng(32);
  const std::vector<Image> frames{random_frame(4, 2, rng), random_frame(4, 2, rng)};
  const Image joined = compose_film_strip(frames, 0, {9, 9, 9, 9});
  ASSERT_EQ(joined.width, 8);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 8; ++x) {
      const Image& source = frames[x < 4 ? 0 : 1];
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(joined.pixel(x, y)[c], source.pixel(x % 4, y)[c]);
    }
  }
  const Image single = compose_film_strip(std::span(frames).first(1), 7, {9, 9, 9, 9});
  EXPECT_EQ(single.width, 4);
  EXPECT_TRUE(single.rgba == frames[0].rgba);
}

TEST(FilmStrip, RejectsBadInput) {
  std::mt19937 rng(33);
  EXPECT_THROW(compose_film_strip({}, 2, {0, 0, 0, 255}), std::invalid_argument);
  const std::vector<Image> mixed{random_frame(4, 3, rng), random_frame(4, 4, rng)};
  try {
    compose_film_strip(mixed, 2, {0, 0, 0, 255});
    ADD_FAILURE() << "frames of different sizes were accepted";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("frame 1"), std::string::npos) << message;
    EXPECT_NE(message.find("4×4"), std::string::npos) << message;
    EXPECT_NE(message.find("4×3"), std::string::npos) << message;
  }
  const std::vector<Image> same{random_frame(4, 3, rng), random_frame(4, 3, rng)};
  EXPECT_THROW(compose_film_strip(same, -1, {0, 0, 0, 255}), std::invalid_argument);
  std::vector<Image> malformed = same;
  malformed[1].rgba.pop_back();
  EXPECT_THROW(compose_film_strip(malformed, 1, {0, 0, 0, 255}), std::invalid_argument);
  EXPECT_THROW(compose_film_strip(same, std::numeric_limits<int>::max(), {0, 0, 0, 255}),
               std::invalid_argument);
}

TEST(FilmStripIndices, SpreadEvenlyRoundedHalfUp) {
  // 149·i/4 = 0, 37.25, 74.5, 111.75, 149: halves round up.
  EXPECT_EQ(strip_frame_indices(0, 149, 5), (std::vector<std::size_t>{0, 37, 75, 112, 149}));
  EXPECT_EQ(strip_frame_indices(10, 20, 2), (std::vector<std::size_t>{10, 20}));
  EXPECT_EQ(strip_frame_indices(100, 110, 3), (std::vector<std::size_t>{100, 105, 110}));
  // 0, 1.5, 3 → 0, 2, 3.
  EXPECT_EQ(strip_frame_indices(0, 3, 3), (std::vector<std::size_t>{0, 2, 3}));
}

TEST(FilmStripIndices, FewerWhenTheRangeHoldsFewer) {
  EXPECT_EQ(strip_frame_indices(10, 14, 10), (std::vector<std::size_t>{10, 11, 12, 13, 14}));
  EXPECT_EQ(strip_frame_indices(10, 14, 5), (std::vector<std::size_t>{10, 11, 12, 13, 14}));
  EXPECT_EQ(strip_frame_indices(7, 7, 4), (std::vector<std::size_t>{7}));
}

TEST(FilmStripIndices, OneGivesTheMiddleZeroGivesNone) {
  EXPECT_EQ(strip_frame_indices(0, 148, 1), (std::vector<std::size_t>{74}));
  EXPECT_EQ(strip_frame_indices(0, 149, 1), (std::vector<std::size_t>{75}));  // 74.5 up
  EXPECT_EQ(strip_frame_indices(5, 5, 1), (std::vector<std::size_t>{5}));
  EXPECT_TRUE(strip_frame_indices(0, 149, 0).empty());
}

TEST(FilmStripIndices, RejectsAnInvertedRange) {
  EXPECT_THROW(strip_frame_indices(10, 9, 3), std::invalid_argument);
}

TEST(FilmStripIndices, HugeRangesDoNotOverflow) {
  const std::size_t top = std::numeric_limits<std::size_t>::max();
  // top/2 = 2^63 − 0.5 rounds up to 2^63.
  EXPECT_EQ(strip_frame_indices(0, top, 3),
            (std::vector<std::size_t>{0, std::size_t{1} << 63, top}));
}

TEST(FilmStripIndices, AgreeWithExactRationalRounding) {
  // Brute force against the definition: |index − first − i·span/d| ≤ 1/2 with halves up, ends
  // included, strictly increasing, min(count, span + 1) of them.
  for (std::size_t first : {0u, 3u, 1000u}) {
    for (std::size_t span = 0; span < 40; ++span) {
      for (std::size_t count = 2; count < 50; ++count) {
        const std::vector<std::size_t> indices = strip_frame_indices(first, first + span, count);
        const std::size_t expected_size = std::min(count, span + 1);
        ASSERT_EQ(indices.size(), expected_size) << span << " " << count;
        EXPECT_EQ(indices.front(), first);
        EXPECT_EQ(indices.back(), first + span);
        for (std::size_t i = 1; i < indices.size(); ++i)
          EXPECT_LT(indices[i - 1], indices[i]);
        if (count <= span + 1) {
          const std::size_t d = count - 1;
          for (std::size_t i = 0; i < count; ++i) {
            // 2·d·(index − first) − 2·i·span in (−d, d]: nearest, halves up.
            const auto twice_error = static_cast<long long>(2 * d * (indices[i] - first)) -
                                     static_cast<long long>(2 * i * span);
            EXPECT_GT(twice_error, -static_cast<long long>(d)) << span << " " << count << " " << i;
            EXPECT_LE(twice_error, static_cast<long long>(d)) << span << " " << count << " " << i;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace rugosim
