#include "render/sinks/png_io.h"

#include <algorithm>
#include <array>
#include <csetjmp>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

#include "support/scratch_dir.h"

namespace rugosim {
namespace {

namespace fs = std::filesystem;

// An image of random pixels with runs (each pixel repeats the last with probability 1/2), so
// that both the literal and the match paths of deflate are exercised.
Image random_image(int width, int height, bool opaque, std::mt19937& rng) {
  Image image(width, height);
  std::uniform_int_distribution<int> byte(0, 255);
  std::array<std::uint8_t, 4> last{0, 0, 0, 255};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (byte(rng) >= 128) {
        for (auto& channel : last)
          channel = static_cast<std::uint8_t>(byte(rng));
        if (opaque) last[3] = 255;
      }
      std::copy(last.begin(), last.end(), image.pixel(x, y));
    }
  }
  return image;
}

using testing::ScratchDir;

void write_bytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

std::uint8_t ihdr_colour_type(const std::vector<std::uint8_t>& png) {
  return png.at(25);  // signature 8, chunk length 4, "IHDR" 4, width 4, height 4, depth 1
}

// ---- A PNG writer for the formats our encoder never makes (classic libpng API) ----

// What to write: samples row-major, one value per channel of the colour type at its bit depth
// (palette indices for palette images).
struct TestPng {
  int width = 0;
  int height = 0;
  int colour_type = PNG_COLOR_TYPE_GRAY;
  int bit_depth = 8;
  bool interlaced = false;
  std::vector<std::uint16_t> samples;
  std::vector<png_color> palette;
  std::vector<png_byte> palette_alpha;      // tRNS of a palette image
  std::optional<png_color_16> transparent;  // tRNS of a gray or RGB image
};

int channels_of(int colour_type) {
  switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY:
    case PNG_COLOR_TYPE_PALETTE:
      return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return 2;
    case PNG_COLOR_TYPE_RGB:
      return 3;
    default:
      return 4;
  }
}

struct TestWrite {
  const TestPng* png = nullptr;
  png_bytepp rows = nullptr;
  std::vector<std::uint8_t>* out = nullptr;
};

extern "C" void test_append(png_structp png, png_bytep data, std::size_t size) {
  auto* write = static_cast<TestWrite*>(png_get_io_ptr(png));
  write->out->insert(write->out->end(), data, data + size);
}

extern "C" void test_flush(png_structp /*png*/) {}

// Plain data only between setjmp and the libpng calls.
bool run_test_write(TestWrite& write) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  const TestPng& spec = *write.png;
  png_set_write_fn(png, &write, test_append, test_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(spec.width),
               static_cast<png_uint_32>(spec.height), spec.bit_depth, spec.colour_type,
               spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!spec.palette.empty()) {
    png_set_PLTE(png, info, spec.palette.data(), static_cast<int>(spec.palette.size()));
  }
  if (!spec.palette_alpha.empty()) {
    png_set_tRNS(png, info, spec.palette_alpha.data(), static_cast<int>(spec.palette_alpha.size()),
                 nullptr);
  }
  if (spec.transparent) png_set_tRNS(png, info, nullptr, 0, &*spec.transparent);
  png_write_info(png, info);
  if (spec.bit_depth < 8) png_set_packing(png);  // rows hold one byte per sample
  png_write_image(png, write.rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

std::vector<std::uint8_t> write_test_png(const TestPng& spec) {
  const std::size_t per_row = static_cast<std::size_t>(spec.width * channels_of(spec.colour_type));
  const std::size_t bytes_per_sample = spec.bit_depth == 16 ? 2 : 1;
  std::vector<std::uint8_t> bytes;
  for (const std::uint16_t sample : spec.samples) {
    if (bytes_per_sample == 2) bytes.push_back(static_cast<std::uint8_t>(sample >> 8));
    bytes.push_back(static_cast<std::uint8_t>(sample & 0xff));
  }
  std::vector<png_bytep> rows;
  for (int y = 0; y < spec.height; ++y) {
    rows.push_back(bytes.data() + static_cast<std::size_t>(y) * per_row * bytes_per_sample);
  }
  std::vector<std::uint8_t> out;
  TestWrite write;
  write.png = &spec;
  write.rows = rows.data();
  write.out = &out;
  EXPECT_TRUE(run_test_write(write));
  return out;
}

// Sample values at `depth` bits, random, row-major.
std::vector<std::uint16_t> random_samples(std::size_t count, int depth, std::mt19937& rng) {
  std::uniform_int_distribution<int> value(0, (1 << depth) - 1);
  std::vector<std::uint16_t> samples;
  for (std::size_t i = 0; i < count; ++i)
    samples.push_back(static_cast<std::uint16_t>(value(rng)));
  return samples;
}

// A sample of `depth` bits as 8 bits: low depths scaled to 0..255, 16 bits rounded to nearest.
std::uint8_t to_8_bits(unsigned value, int depth) {
  if (depth == 16) return static_cast<std::uint8_t>((value * 255u + 32767u) / 65535u);
  return static_cast<std::uint8_t>(value * 255u / ((1u << depth) - 1u));
}

// The RGBA8 that a gray, gray + alpha, RGB or RGBA file stands for, from its samples.
Image expected_direct(const TestPng& spec) {
  Image image(spec.width, spec.height);
  const int channels = channels_of(spec.colour_type);
  const bool colour = (spec.colour_type & PNG_COLOR_MASK_COLOR) != 0;
  const bool alpha = (spec.colour_type & PNG_COLOR_MASK_ALPHA) != 0;
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const std::uint16_t* s =
          spec.samples.data() + static_cast<std::size_t>((y * spec.width + x) * channels);
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        p[c] = to_8_bits(s[colour ? c : 0], spec.bit_depth);
      p[3] = alpha ? to_8_bits(s[channels - 1], spec.bit_depth) : 255;
      if (spec.transparent) {
        const bool hit = colour
                             ? s[0] == spec.transparent->red && s[1] == spec.transparent->green &&
                                   s[2] == spec.transparent->blue
                             : s[0] == spec.transparent->gray;
        p[3] = hit ? 0 : 255;
      }
    }
  }
  return image;
}

Image expected_palette(const TestPng& spec) {
  Image image(spec.width, spec.height);
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const std::uint16_t index = spec.samples[static_cast<std::size_t>(y * spec.width + x)];
      const png_color& entry = spec.palette.at(index);
      std::uint8_t* p = image.pixel(x, y);
      p[0] = entry.red;
      p[1] = entry.green;
      p[2] = entry.blue;
      p[3] = index < spec.palette_alpha.size() ? spec.palette_alpha[index] : 255;
    }
  }
  return image;
}

void expect_same_pixels(const Image& actual, const Image& expected, const std::string& what) {
  ASSERT_EQ(actual.width, expected.width) << what;
  ASSERT_EQ(actual.height, expected.height) << what;
  ASSERT_EQ(actual.rgba.size(), expected.rgba.size()) << what;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(actual.pixel(x, y)[c], expected.pixel(x, y)[c])
            << what << " at (" << x << ", " << y << ") channel " << c;
      }
    }
  }
}

std::string read_error_message(const std::string& path) {
  try {
    read_png_file(path);
  } catch (const PngReadError& error) {
    return error.what();
  }
  ADD_FAILURE() << "reading " << path << " did not throw PngReadError";
  return "";
}

// ---- Tests ----

TEST(PngFilterNames, ParseWhatTheyPrint) {
  for (const PngFilter filter : {PngFilter::kNone, PngFilter::kSub, PngFilter::kUp,
                                 PngFilter::kAverage, PngFilter::kPaeth, PngFilter::kAll}) {
    EXPECT_EQ(parse_png_filter(png_filter_name(filter)), filter);
  }
  EXPECT_EQ(parse_png_filter("paeth"), PngFilter::kPaeth);
  for (const char* bad : {"", "Up", "avg", "adaptive", "none "}) {
    EXPECT_FALSE(parse_png_filter(bad).has_value()) << bad;
  }
}

TEST(PngRoundTrip, EveryFilterLevelStrategyAndChannelLayout) {
  std::mt19937 rng(20240611);
  const std::vector<std::array<int, 2>> sizes{{1, 1}, {3, 2}, {1, 17}, {17, 9}, {257, 131}};
  for (const auto& [width, height] : sizes) {
    for (const bool keep_alpha : {false, true}) {
      const Image image = random_image(width, height, !keep_alpha, rng);
      for (const PngFilter filter : {PngFilter::kNone, PngFilter::kSub, PngFilter::kUp,
                                     PngFilter::kAverage, PngFilter::kPaeth, PngFilter::kAll}) {
        for (const int level : {0, 1, 6, 9}) {
          for (const bool rle : {false, true}) {
            const PngSettings settings{level, filter, rle, keep_alpha};
            const std::string what = std::to_string(width)
                                         .append("x")
                                         .append(std::to_string(height))
                                         .append(" filter ")
                                         .append(png_filter_name(filter))
                                         .append(" level ")
                                         .append(std::to_string(level))
                                         .append(rle ? " rle" : "")
                                         .append(keep_alpha ? " rgba" : " rgb");
            const std::vector<std::uint8_t> png = encode_png(image, settings);
            EXPECT_EQ(ihdr_colour_type(png), keep_alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB)
                << what;
            expect_same_pixels(decode_png(png), image, what);
          }
        }
      }
    }
  }
}

TEST(PngRoundTrip, RgbModeWritesAlphaAs255) {
  std::mt19937 rng(7);
  const Image translucent = random_image(31, 7, false, rng);
  Image opaque = translucent;
  for (std::size_t i = 3; i < opaque.rgba.size(); i += 4)
    opaque.rgba[i] = 255;
  expect_same_pixels(decode_png(encode_png(translucent, PngSettings{})), opaque, "rgb");
}

TEST(PngEncode, RejectsMalformedImagesAndLevels) {
  Image empty;
  EXPECT_THROW(encode_png(empty, PngSettings{}), std::invalid_argument);
  Image short_buffer(4, 4);
  short_buffer.rgba.pop_back();
  EXPECT_THROW(encode_png(short_buffer, PngSettings{}), std::invalid_argument);
  const Image fine(2, 2);
  EXPECT_THROW(encode_png(fine, PngSettings{10, PngFilter::kUp, true, false}),
               std::invalid_argument);
  EXPECT_THROW(encode_png(fine, PngSettings{-1, PngFilter::kUp, true, false}),
               std::invalid_argument);
}

TEST(PngDecode, GrayAtEveryBitDepthInterlacedOrNot) {
  std::mt19937 rng(11);
  for (const int depth : {1, 2, 4, 8, 16}) {
    for (const bool interlaced : {false, true}) {
      TestPng spec;
      spec.width = 13;
      spec.height = 11;
      spec.colour_type = PNG_COLOR_TYPE_GRAY;
      spec.bit_depth = depth;
      spec.interlaced = interlaced;
      spec.samples = random_samples(13 * 11, depth, rng);
      expect_same_pixels(decode_png(write_test_png(spec)), expected_direct(spec),
                         std::string("gray ")
                             .append(std::to_string(depth))
                             .append(interlaced ? " interlaced" : ""));
    }
  }
}

TEST(PngDecode, GrayAlphaRgbAndRgbaAt8And16Bits) {
  std::mt19937 rng(12);
  for (const int colour_type :
       {PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA}) {
    for (const int depth : {8, 16}) {
      for (const bool interlaced : {false, true}) {
        TestPng spec;
        spec.width = 9;
        spec.height = 10;
        spec.colour_type = colour_type;
        spec.bit_depth = depth;
        spec.interlaced = interlaced;
        spec.samples =
            random_samples(static_cast<std::size_t>(9 * 10 * channels_of(colour_type)), depth, rng);
        // The ends of the range and the exact 8-bit values v × 257 must map exactly.
        spec.samples[0] = 0;
        spec.samples[1] = static_cast<std::uint16_t>((1 << depth) - 1);
        if (depth == 16) spec.samples[2] = 128 * 257;
        expect_same_pixels(decode_png(write_test_png(spec)), expected_direct(spec),
                           std::string("type ")
                               .append(std::to_string(colour_type))
                               .append(" depth ")
                               .append(std::to_string(depth))
                               .append(interlaced ? " interlaced" : ""));
      }
    }
  }
}

TEST(PngDecode, TransparentColourBecomesAlpha) {
  std::mt19937 rng(13);
  for (const int depth : {4, 8, 16}) {
    TestPng spec;
    spec.width = 12;
    spec.height = 5;
    spec.colour_type = PNG_COLOR_TYPE_GRAY;
    spec.bit_depth = depth;
    spec.samples = random_samples(12 * 5, depth, rng);
    png_color_16 key{};
    key.gray = spec.samples[7];
    spec.transparent = key;
    expect_same_pixels(decode_png(write_test_png(spec)), expected_direct(spec),
                       std::string("gray tRNS ").append(std::to_string(depth)));
  }
  TestPng rgb;
  rgb.width = 6;
  rgb.height = 6;
  rgb.colour_type = PNG_COLOR_TYPE_RGB;
  rgb.bit_depth = 8;
  rgb.samples = random_samples(6 * 6 * 3, 2, rng);  // few colours, so that the key repeats
  png_color_16 key{};
  key.red = rgb.samples[0];
  key.green = rgb.samples[1];
  key.blue = rgb.samples[2];
  rgb.transparent = key;
  expect_same_pixels(decode_png(write_test_png(rgb)), expected_direct(rgb), "rgb tRNS");
}

TEST(PngDecode, PaletteWithPartialTransparency) {
  std::mt19937 rng(14);
  for (const int depth : {1, 2, 4, 8}) {
    for (const bool interlaced : {false, true}) {
      TestPng spec;
      spec.width = 10;
      spec.height = 9;
      spec.colour_type = PNG_COLOR_TYPE_PALETTE;
      spec.bit_depth = depth;
      spec.interlaced = interlaced;
      const int entries = std::min(1 << depth, 40);
      std::uniform_int_distribution<int> byte(0, 255);
      for (int i = 0; i < entries; ++i) {
        spec.palette.push_back(png_color{static_cast<png_byte>(byte(rng)),
                                         static_cast<png_byte>(byte(rng)),
                                         static_cast<png_byte>(byte(rng))});
      }
      // Alpha for the first half of the entries only: the rest are opaque.
      for (int i = 0; i < (entries + 1) / 2; ++i) {
        spec.palette_alpha.push_back(static_cast<png_byte>(byte(rng)));
      }
      std::uniform_int_distribution<int> index(0, entries - 1);
      for (int i = 0; i < 10 * 9; ++i)
        spec.samples.push_back(static_cast<std::uint16_t>(index(rng)));
      expect_same_pixels(decode_png(write_test_png(spec)), expected_palette(spec),
                         std::string("palette ")
                             .append(std::to_string(depth))
                             .append(interlaced ? " interlaced" : ""));
    }
  }
}

TEST(PngReadErrors, NameTheFileAndWhatIsWrong) {
  const ScratchDir directory("png_io_test");
  const std::string missing = (directory.path() / "missing.png").string();
  std::string message = read_error_message(missing);
  EXPECT_NE(message.find(missing), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;

  const std::string empty = (directory.path() / "empty.png").string();
  write_bytes(empty, {});
  message = read_error_message(empty);
  EXPECT_NE(message.find(empty), std::string::npos) << message;
  EXPECT_NE(message.find("not a PNG file"), std::string::npos) << message;

  std::mt19937 rng(15);
  std::vector<std::uint8_t> garbage;
  for (int i = 0; i < 1000; ++i)
    garbage.push_back(static_cast<std::uint8_t>(rng()));
  const std::string garbage_path = (directory.path() / "garbage.png").string();
  write_bytes(garbage_path, garbage);
  message = read_error_message(garbage_path);
  EXPECT_NE(message.find(garbage_path), std::string::npos) << message;
  EXPECT_NE(message.find("not a PNG file"), std::string::npos) << message;

  // A directory is not a file.
  message = read_error_message(directory.path().string());
  EXPECT_NE(message.find(directory.path().string()), std::string::npos) << message;
}

TEST(PngReadErrors, EveryTruncationIsReported) {
  std::mt19937 rng(16);
  const std::vector<std::uint8_t> png = encode_png(random_image(5, 4, true, rng), PngSettings{});
  ASSERT_GT(png.size(), 8u);
  for (std::size_t length = 0; length < png.size(); ++length) {
    const std::span<const std::uint8_t> prefix(png.data(), length);
    try {
      decode_png(prefix, "cut.png");
      ADD_FAILURE() << "a prefix of " << length << " bytes decoded";
    } catch (const PngReadError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("cut.png: ", 0), 0u) << message;
      const char* expected = length < 8 ? "not a PNG file" : "truncated";
      EXPECT_NE(message.find(expected), std::string::npos) << length << ": " << message;
    }
  }
  // And through a file.
  const ScratchDir directory("png_io_test");
  const std::string path = (directory.path() / "cut.png").string();
  write_bytes(path, std::vector<std::uint8_t>(png.begin(), png.begin() + 40));
  const std::string message = read_error_message(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(PngReadErrors, CorruptHeaderGivesLibpngsReason) {
  std::mt19937 rng(17);
  std::vector<std::uint8_t> png = encode_png(random_image(5, 4, true, rng), PngSettings{});
  png[17] ^= 0x40;  // a byte of the width: the IHDR checksum no longer matches
  try {
    decode_png(png, "bad.png");
    ADD_FAILURE() << "a corrupt header decoded";
  } catch (const PngReadError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("bad.png: invalid PNG: ", 0), 0u) << message;
    EXPECT_NE(message.find("CRC"), std::string::npos) << message;
  }
}

TEST(PngWriteFile, DevFullReportsNoSpace) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const Image image(16, 16);
  try {
    write_png_file("/dev/full", image, PngSettings{});
    ADD_FAILURE() << "writing to /dev/full succeeded";
  } catch (const SinkError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  }
}

TEST(PngWriteFile, AtomicWriteLeavesOnlyTheFile) {
  const ScratchDir directory("png_io_test");
  std::mt19937 rng(18);
  const Image first = random_image(40, 30, true, rng);
  const Image second = random_image(20, 10, true, rng);
  const std::string path = (directory.path() / "frame.png").string();
  write_png_file(path, first, PngSettings{});
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"frame.png"});
  expect_same_pixels(read_png_file(path), first, "first");
  // Replacing an existing file.
  write_png_file(path, second, PngSettings{});
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"frame.png"});
  expect_same_pixels(read_png_file(path), second, "second");
  // Through a symbolic link: the link stays, the file it points to is replaced.
  const fs::path link = directory.path() / "link.png";
  fs::create_symlink("frame.png", link);
  write_png_file(link.string(), first, PngSettings{});
  EXPECT_EQ(directory.listing(), (std::vector<std::string>{"frame.png", "link.png"}));
  EXPECT_TRUE(fs::is_symlink(link));
  expect_same_pixels(read_png_file(path), first, "through the link");
}

TEST(PngWriteFile, FailedWriteRemovesTheTemporaryFileAndKeepsTheOldOne) {
  const ScratchDir directory("png_io_test");
  std::mt19937 rng(19);
  const std::string path = (directory.path() / "frame.png").string();
  const Image old_image = random_image(8, 8, true, rng);
  write_png_file(path, old_image, PngSettings{});

  // A file size limit makes write(2) fail with EFBIG part way through the temporary file
  // (SIGXFSZ ignored so that the process is not stopped). Restored before any assertion.
  const Image big = random_image(200, 200, true, rng);
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  rlimit small = saved;
  small.rlim_cur = 1000;
  const auto saved_handler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_png_file(path, big, PngSettings{});
  } catch (const SinkError& error) {
    message = error.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, saved_handler);

  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"frame.png"});
  expect_same_pixels(read_png_file(path), old_image, "the file before the failed write");

  // Into a directory that does not exist: nothing created anywhere.
  const std::string nowhere = (directory.path() / "no" / "frame.png").string();
  try {
    write_png_file(nowhere, big, PngSettings{});
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const SinkError& error) {
    message = error.what();
    EXPECT_NE(message.find(nowhere), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"frame.png"});
}

}  // namespace
}  // namespace rugosim
