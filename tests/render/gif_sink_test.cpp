// The GIF sink (gif_sink.h), checked by decoding what it wrote with libavcodec
// (support/video_probe.h): codec, size, frame count and duration; colours kept exactly when a
// clip has fewer than 256; the loop-forever extension; the file put in place only by close(),
// whole, and an earlier file kept otherwise; errors naming the path.
#include "render/sinks/gif_sink.h"

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

#include "support/file_text.h"
#include "support/video_probe.h"

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

std::string sink_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const SinkError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no SinkError thrown";
  return {};
}

class GifSinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_log_level_ = av_log_get_level();
    av_log_set_level(AV_LOG_ERROR);
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::path(::testing::TempDir()) / std::string("rugosim_gif_")
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

TEST_F(GifSinkTest, HoldsEveryFrameWithItsColoursAndTheClipsLength) {
  const std::string path = file("bars.gif");
  constexpr int kFrames = 20;
  {
    GifSink sink(path, 96, 40, GifOptions{30});
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

TEST_F(GifSinkTest, LoopsForever) {
  const std::string path = file("loop.gif");
  GifSink sink(path, 16, 16);
  sink.write(shifting_bars(16, 16, 0), 0);
  sink.write(shifting_bars(16, 16, 1), 1);
  sink.close();
  const std::string bytes = testing::read_text(path);
  // The NETSCAPE2.0 application extension: sub-block of 3 bytes, id 1, loop count 0 (forever).
  const std::string loop_forever = std::string("NETSCAPE2.0\x03\x01\x00\x00", 15);
  EXPECT_NE(bytes.find(loop_forever), std::string::npos);
}

TEST_F(GifSinkTest, TheFileAppearsOnlyWhenClosedAndAnEarlierOneIsKeptUntilThen) {
  const std::string path = file("clip.gif");
  testing::write_text(path, "earlier");
  {
    GifSink sink(path, 32, 32);
    sink.write(shifting_bars(32, 32, 0), 0);
    EXPECT_EQ(testing::read_text(path), "earlier");
    // Destroyed without close(): abandoned.
  }
  EXPECT_EQ(testing::read_text(path), "earlier");
  EXPECT_EQ(names(), std::vector<std::string>{"clip.gif"});
  {
    GifSink sink(path, 32, 32);
    sink.write(shifting_bars(32, 32, 0), 0);
    sink.close();
  }
  EXPECT_EQ(testing::probe_video(path).frames, 1u);
  EXPECT_EQ(names(), std::vector<std::string>{"clip.gif"});
}

TEST_F(GifSinkTest, AFailedFrameLeavesNothingAndCloseSaysSo) {
  const std::string path = file("clip.gif");
  GifSink sink(path, 32, 32);
  sink.write(shifting_bars(32, 32, 0), 0);
  const std::string wrong = sink_error_of([&] { sink.write(shifting_bars(30, 32, 1), 1); });
  EXPECT_NE(wrong.find(path), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("30x32"), std::string::npos) << wrong;
  const std::string closing = sink_error_of([&] { sink.close(); });
  EXPECT_NE(closing.find("incomplete"), std::string::npos) << closing;
  EXPECT_TRUE(names().empty());
  sink.close();  // idempotent
  const std::string late = sink_error_of([&] { sink.write(shifting_bars(32, 32, 2), 2); });
  EXPECT_NE(late.find("after the GIF was closed"), std::string::npos) << late;
}

TEST_F(GifSinkTest, NoFrameWritesNothing) {
  GifSink sink(file("empty.gif"), 8, 8);
  EXPECT_NE(sink_error_of([&] { sink.close(); }).find("no frame"), std::string::npos);
  EXPECT_TRUE(names().empty());
}

TEST_F(GifSinkTest, MissingFolderFailsAtConstructionNamingThePath) {
  const std::string path = file("no/such/folder/clip.gif");
  const std::string error = sink_error_of([&] { GifSink sink(path, 8, 8); });
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

TEST_F(GifSinkTest, FullDeviceIsASinkErrorNamingThePathAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const std::string error = sink_error_of([&] {
    GifSink sink("/dev/full", 64, 64);
    for (int k = 0; k < 8; ++k)
      sink.write(shifting_bars(64, 64, k), static_cast<std::size_t>(k));
    sink.close();
  });
  EXPECT_NE(error.find("/dev/full"), std::string::npos) << error;
  EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
}

TEST_F(GifSinkTest, SizesAndRatesAGifCannotHoldAreInvalidArguments) {
  EXPECT_THROW(GifSink(file("a.gif"), 0, 8), std::invalid_argument);
  EXPECT_THROW(GifSink(file("a.gif"), 8, 65536), std::invalid_argument);
  EXPECT_THROW(GifSink(file("a.gif"), 8, 8, GifOptions{60}), std::invalid_argument);
  EXPECT_THROW(GifSink(file("a.gif"), 8, 8, GifOptions{0}), std::invalid_argument);
  EXPECT_THROW(GifSink(file("a.gif"), 8, 8, GifOptions{std::nan("")}), std::invalid_argument);
  EXPECT_TRUE(gif_fps_is_valid(50));
  EXPECT_FALSE(gif_fps_is_valid(50.5));
  EXPECT_TRUE(names().empty());
}

}  // namespace
}  // namespace rugosim
