// The encoded clip sink (encoded_clip_sink.h), checked by decoding what it wrote with
// libavcodec (support/video_probe.h; VP9 through libvpx-vp9, which keeps alpha) or, for WebP,
// libwebp (support/webp_probe.h): codec, size, frame count and duration; colours (exact for a
// GIF of fewer than 256) and alpha; the loop-forever extension; the file put in place only by
// close(), whole, and an earlier file kept otherwise; errors naming the path.
#include "render/sinks/encoded_clip_sink.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

extern "C" {
#include <libavutil/log.h>
}

#include "support/file_size_limit.h"
#include "support/file_text.h"
#include "support/sink_error.h"
#include "support/video_probe.h"
#include "support/webp_probe.h"

namespace rugosim {
namespace {

namespace fs = std::filesystem;

// Frame k: vertical bars of eight colours, shifted k bars to the right (every frame differs,
// and the whole clip has eight colours, so the palette holds them exactly).
Image shifting_bars(int width, int height, int k) {
  static const std::uint8_t kBars[8][3] = {{255, 255, 255}, {230, 200, 20}, {20, 200, 210},
                                           {30, 180, 40},   {200, 40, 190}, {210, 30, 30},
                                           {20, 40, 200},   {12, 12, 12}};
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int bar = ((x * 8) / width + k) % 8;
      std::uint8_t* p = image.pixel(x, y);
      p[0] = kBars[bar][0];
      p[1] = kBars[bar][1];
      p[2] = kBars[bar][2];
      p[3] = 255;
    }
  }
  return image;
}

using testing::sink_error_of;

class EncodedClipSinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_log_level_ = av_log_get_level();
    av_log_set_level(AV_LOG_ERROR);
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::path(::testing::TempDir()) / std::string("rugosim_clip_")
                                                   .append(info->name())
                                                   .append("_")
                                                   .append(std::to_string(getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
    av_log_set_level(previous_log_level_);
  }
  std::string file(const std::string& name) const { return (folder_ / name).string(); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(folder_))
      out.push_back(entry.path().filename().string());
    return out;
  }

  fs::path folder_;
  int previous_log_level_ = 0;
};

TEST_F(EncodedClipSinkTest, HoldsEveryFrameWithItsColoursAndTheClipsLength) {
  const std::string path = file("bars.gif");
  constexpr int kFrames = 20;
  {
    EncodedClipSink sink(path, ClipFormat::kGif, 96, 40, ClipOptions{30});
    for (int k = 0; k < kFrames; ++k)
      sink.write(shifting_bars(96, 40, k), static_cast<std::size_t>(k));
    EXPECT_EQ(sink.frames_written(), static_cast<std::size_t>(kFrames));
    sink.close();
  }
  const testing::VideoProbe probe = testing::probe_video(path, true);
  EXPECT_EQ(probe.codec, "gif");
  EXPECT_EQ(probe.width, 96);
  EXPECT_EQ(probe.height, 40);
  ASSERT_EQ(probe.frames, static_cast<std::size_t>(kFrames));
  // Delays are whole centiseconds (3 and 4 at 30 fps): the clip keeps its length within one.
  EXPECT_NEAR(probe.duration_s, kFrames / 30.0, 0.01 + 1e-9);
  ASSERT_EQ(probe.decoded_rgba.size(), static_cast<std::size_t>(kFrames));
  for (int k = 0; k < kFrames; ++k) {
    const Image expected = shifting_bars(96, 40, k);
    EXPECT_EQ(probe.decoded_rgba[static_cast<std::size_t>(k)].rgba, expected.rgba)
        << "frame " << k << ": eight colours fit the palette exactly";
  }
  EXPECT_EQ(names(), std::vector<std::string>{"bars.gif"}) << "no temporary file left";
}

TEST_F(EncodedClipSinkTest, LoopsForever) {
  const std::string path = file("loop.gif");
  EncodedClipSink sink(path, ClipFormat::kGif, 16, 16);
  sink.write(shifting_bars(16, 16, 0), 0);
  sink.write(shifting_bars(16, 16, 1), 1);
  sink.close();
  const std::string bytes = testing::read_text(path);
  // The NETSCAPE2.0 application extension: sub-block of 3 bytes, id 1, loop count 0 (forever).
  const std::string loop_forever = std::string("NETSCAPE2.0\x03\x01\x00\x00", 15);
  EXPECT_NE(bytes.find(loop_forever), std::string::npos);
}

TEST_F(EncodedClipSinkTest, TheFileAppearsOnlyWhenClosedAndAnEarlierOneIsKeptUntilThen) {
  const std::string path = file("clip.gif");
  testing::write_text(path, "earlier");
  {
    EncodedClipSink sink(path, ClipFormat::kGif, 32, 32);
    sink.write(shifting_bars(32, 32, 0), 0);
    EXPECT_EQ(testing::read_text(path), "earlier");
    // Destroyed without close(): abandoned.
  }
  EXPECT_EQ(testing::read_text(path), "earlier");
  EXPECT_EQ(names(), std::vector<std::string>{"clip.gif"});
  {
    EncodedClipSink sink(path, ClipFormat::kGif, 32, 32);
    sink.write(shifting_bars(32, 32, 0), 0);
    sink.close();
  }
  EXPECT_EQ(testing::probe_video(path).frames, 1u);
  EXPECT_EQ(names(), std::vector<std::string>{"clip.gif"});
}

TEST_F(EncodedClipSinkTest, AFailedFrameLeavesNothingAndCloseSaysSo) {
  const std::string path = file("clip.gif");
  EncodedClipSink sink(path, ClipFormat::kGif, 32, 32);
  sink.write(shifting_bars(32, 32, 0), 0);
  const std::string wrong = sink_error_of([&] { sink.write(shifting_bars(30, 32, 1), 1); });
  EXPECT_NE(wrong.find(path), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("30x32"), std::string::npos) << wrong;
  const std::string closing = sink_error_of([&] { sink.close(); });
  EXPECT_NE(closing.find("incomplete"), std::string::npos) << closing;
  EXPECT_TRUE(names().empty());
  sink.close();  // idempotent
  const std::string late = sink_error_of([&] { sink.write(shifting_bars(32, 32, 2), 2); });
  EXPECT_NE(late.find("after the gif was closed"), std::string::npos) << late;
}

TEST_F(EncodedClipSinkTest, NoFrameWritesNothing) {
  EncodedClipSink sink(file("empty.gif"), ClipFormat::kGif, 8, 8);
  EXPECT_NE(sink_error_of([&] { sink.close(); }).find("no frame"), std::string::npos);
  EXPECT_TRUE(names().empty());
}

TEST_F(EncodedClipSinkTest, MissingFolderFailsAtConstructionNamingThePath) {
  const std::string path = file("no/such/folder/clip.gif");
  const std::string error =
      sink_error_of([&] { EncodedClipSink sink(path, ClipFormat::kGif, 8, 8); });
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

TEST_F(EncodedClipSinkTest, FullDeviceIsASinkErrorNamingThePathAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const std::string error = sink_error_of([&] {
    EncodedClipSink sink("/dev/full", ClipFormat::kGif, 64, 64);
    for (int k = 0; k < 8; ++k)
      sink.write(shifting_bars(64, 64, k), static_cast<std::size_t>(k));
    sink.close();
  });
  EXPECT_NE(error.find("/dev/full"), std::string::npos) << error;
  EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
}

// A disk that fills up in the middle of a clip (a file size limit stands in for it): the header
// goes through, a later packet does not. The packets are written on the sink's encoding thread,
// so the failure reaches the writer from there: a later write() or close() reports it with the
// path and the reason, the sink closes all the same, and nothing is left beside the target.
TEST_F(EncodedClipSinkTest, DiskFullMidClipIsASinkErrorFromWriteOrClose) {
  const std::string path = file("limited.webm");
  const testing::FileSizeLimit limit(8 * 1024);  // bytes: the header and a frame or two of noise
  std::string message;
  {
    // At 5 frames a second the muxer writes a cluster every 25 frames (5 s), before the end.
    EncodedClipSink sink(path, ClipFormat::kWebm, 160, 120, ClipOptions{5});
    message = testing::sink_error_writing_noise(sink, 160, 120, 60);
  }
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_NE(message.find("writing a packet"), std::string::npos) << message << ": not mid-clip";
  EXPECT_TRUE(names().empty()) << "neither the clip nor its temporary file is left";
}

// Determinism reaches the bytes: the same frames make the same file in every format (WebM's
// muxer would otherwise write a random segment UID), so a clip can be compared by its hash.
TEST_F(EncodedClipSinkTest, TheSameFramesMakeTheSameFileInEveryFormat) {
  for (const ClipFormat format :
       {ClipFormat::kGif, ClipFormat::kWebm, ClipFormat::kMov, ClipFormat::kWebp}) {
    std::string bytes[2];
    for (int run = 0; run < 2; ++run) {
      const std::string path = file(std::string("same")
                                        .append(std::to_string(run))
                                        .append(".")
                                        .append(clip_format_name(format)));
      EncodedClipSink sink(path, format, 64, 48);
      for (int k = 0; k < 6; ++k)
        sink.write(shifting_bars(64, 48, k), static_cast<std::size_t>(k));
      sink.close();
      bytes[run] = testing::read_text(path);
    }
    EXPECT_FALSE(bytes[0].empty());
    EXPECT_TRUE(bytes[0] == bytes[1]) << clip_format_name(format) << ": the two files differ";
  }
}

TEST_F(EncodedClipSinkTest, SizesAndRatesAFormatCannotHoldAreInvalidArguments) {
  const auto make = [&](ClipFormat f, int w, int h, double fps) {
    EncodedClipSink sink(file("a.clip"), f, w, h, ClipOptions{fps});
  };
  EXPECT_THROW(make(ClipFormat::kGif, 0, 8, 30), std::invalid_argument);
  EXPECT_THROW(make(ClipFormat::kWebm, 8, 16385, 30), std::invalid_argument);
  EXPECT_THROW(make(ClipFormat::kGif, 8, 8, 60), std::invalid_argument);
  EXPECT_THROW(make(ClipFormat::kMov, 8, 8, 0), std::invalid_argument);
  EXPECT_THROW(make(ClipFormat::kWebp, 8, 8, std::nan("")), std::invalid_argument);
  EXPECT_TRUE(clip_fps_is_valid(ClipFormat::kGif, 50));
  EXPECT_FALSE(clip_fps_is_valid(ClipFormat::kGif, 50.5));
  EXPECT_TRUE(clip_fps_is_valid(ClipFormat::kWebm, 60));
  EXPECT_TRUE(names().empty());
  for (const ClipFormat f :
       {ClipFormat::kGif, ClipFormat::kWebm, ClipFormat::kMov, ClipFormat::kWebp}) {
    EXPECT_EQ(parse_clip_format(clip_format_name(f)), f);
  }
  EXPECT_FALSE(parse_clip_format("mp4").has_value());
}

// Frame k of the alpha test: the left half transparent (its colour arbitrary), the right half
// the shifting bars, opaque.
Image half_transparent(int width, int height, int k) {
  Image image = shifting_bars(width, height, k);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width / 2; ++x)
      image.pixel(x, y)[3] = 0;
  }
  return image;
}

// Decoded frames of a clip: libavcodec's, or libwebp's for WebP.
std::vector<Image> decode(ClipFormat format, const std::string& path) {
  if (format == ClipFormat::kWebp) return testing::probe_webp(path).frames;
  return testing::probe_video(path, true).decoded_rgba;
}

// Pixels at least `margin` px from a bar's edge and from the middle of the frame: where
// subsampled chroma and lossy coding leave the flat colours alone.
bool interior(int width, int x, int margin) {
  const auto bar = [&](int at) { return (at * 8) / width; };
  if (std::abs(x - width / 2) < margin) return false;
  return x >= margin && x + margin < width && bar(x - margin) == bar(x + margin);
}

struct LossyCase {
  ClipFormat format;
  std::string codec;     // FFmpeg's name ("" for WebP, which FFmpeg cannot decode)
  int colour_tolerance;  // levels, on interior pixels
};

class LossyClips : public EncodedClipSinkTest, public ::testing::WithParamInterface<LossyCase> {};

// Odd sides on purpose: the chroma planes of VP9's 4:2:0 round up.
TEST_P(LossyClips, HoldEveryFrameAtTheClipsRateWithItsColours) {
  const LossyCase& c = GetParam();
  const std::string path = file("bars." + std::string(clip_format_name(c.format)));
  constexpr int kFrames = 12;
  constexpr int kWidth = 97;
  constexpr int kHeight = 41;
  {
    EncodedClipSink sink(path, c.format, kWidth, kHeight, ClipOptions{24});
    for (int k = 0; k < kFrames; ++k)
      sink.write(shifting_bars(kWidth, kHeight, k), static_cast<std::size_t>(k));
    sink.close();
  }
  EXPECT_EQ(names().size(), 1u) << "no temporary file left";
  std::vector<Image> frames;
  if (c.format == ClipFormat::kWebp) {
    const testing::WebpProbe probe = testing::probe_webp(path);
    EXPECT_EQ(probe.width, kWidth);
    EXPECT_EQ(probe.height, kHeight);
    EXPECT_EQ(probe.loop_count, 0);
    ASSERT_EQ(probe.timestamps.size(), static_cast<std::size_t>(kFrames));
    // Millisecond delays: frame k ends at round(1000 (k + 1) / 24) ms, within one.
    EXPECT_NEAR(probe.timestamps.back(), 1000.0 * kFrames / 24.0, 1.0);
    frames = probe.frames;
  } else {
    const testing::VideoProbe probe = testing::probe_video(path, true);
    EXPECT_EQ(probe.codec, c.codec);
    EXPECT_EQ(probe.width, kWidth);
    EXPECT_EQ(probe.height, kHeight);
    // Matroska counts milliseconds.
    EXPECT_NEAR(probe.duration_s, kFrames / 24.0, 2e-3);
    frames = probe.decoded_rgba;
  }
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
  int worst = 0;
  for (int k = 0; k < kFrames; ++k) {
    const Image expected = shifting_bars(kWidth, kHeight, k);
    const Image& got = frames[static_cast<std::size_t>(k)];
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        if (!interior(kWidth, x, 3)) continue;
        for (int ch = 0; ch < 4; ++ch)
          worst = std::max(worst, std::abs(got.pixel(x, y)[ch] - expected.pixel(x, y)[ch]));
      }
    }
  }
  EXPECT_LE(worst, c.colour_tolerance);
  std::printf("%s: worst interior difference %d levels\n",
              std::string(clip_format_name(c.format)).c_str(), worst);
}

// Stated tolerances on flat colours away from edges: ProRes 4444 is near lossless at 10 bits
// (measured: 0 levels, once its BT.709 tags are right; 27 without them), VP9 at crf 24 and
// WebP at quality 90 are lossy 4:2:0 (measured: 7 and 5).
INSTANTIATE_TEST_SUITE_P(Formats, LossyClips,
                         ::testing::Values(LossyCase{ClipFormat::kWebm, "vp9", 10},
                                           LossyCase{ClipFormat::kMov, "prores", 2},
                                           LossyCase{ClipFormat::kWebp, "", 8}),
                         [](const auto& p) {
                           return std::string(clip_format_name(p.param.format));
                         });

class AlphaClips : public EncodedClipSinkTest, public ::testing::WithParamInterface<ClipFormat> {};

TEST_P(AlphaClips, KeepAlphaWhenAskedAndDropItOtherwise) {
  const ClipFormat format = GetParam();
  for (const bool alpha : {true, false}) {
    const std::string path =
        file(std::string(alpha ? "alpha." : "opaque.") + std::string(clip_format_name(format)));
    {
      EncodedClipSink sink(path, format, 64, 32, ClipOptions{30, alpha});
      for (int k = 0; k < 4; ++k)
        sink.write(half_transparent(64, 32, k), static_cast<std::size_t>(k));
      sink.close();
    }
    const std::vector<Image> frames = decode(format, path);
    ASSERT_EQ(frames.size(), 4u) << path;
    int left_most = 0;
    int right_least = 255;
    for (const Image& f : frames) {
      for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
          if (!interior(64, x, 3)) continue;
          const int a = f.pixel(x, y)[3];
          if (x < 32) left_most = std::max(left_most, a);
          if (x >= 32) right_least = std::min(right_least, a);
        }
      }
    }
    // GIF's 1-bit alpha is exact; the others within a few levels.
    if (alpha) {
      EXPECT_LE(left_most, format == ClipFormat::kGif ? 0 : 4) << path;
    } else {
      EXPECT_EQ(left_most, 255) << path << ": opaque clips ignore alpha";
    }
    EXPECT_GE(right_least, format == ClipFormat::kGif ? 255 : 251) << path;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, AlphaClips,
                         ::testing::Values(ClipFormat::kGif, ClipFormat::kWebm, ClipFormat::kMov,
                                           ClipFormat::kWebp),
                         [](const auto& p) { return std::string(clip_format_name(p.param)); });

}  // namespace
}  // namespace rugosim
