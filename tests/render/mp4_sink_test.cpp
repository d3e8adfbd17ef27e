// The MP4 sink (mp4_sink.h), checked by decoding what it wrote with libavcodec
// (support/video_probe.h): frame count, duration, size and codec; the BT.709 colour round trip;
// a SIGKILLed render still playable, and so is the file cut at any byte; I/O errors and bad options
// reported with the path.
#include "render/sinks/mp4_sink.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <signal.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
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

namespace rugosim {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<std::uint8_t, 3>;

Image flat_image(int width, int height, Rgb colour) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = colour[0];
    image.rgba[i + 1] = colour[1];
    image.rgba[i + 2] = colour[2];
    image.rgba[i + 3] = 255;
  }
  return image;
}

// A grey frame with a white 32 px square that moves 3 px right per frame: motion for the
// encoder, no scene cuts (so no keyframes beyond the requested ones).
Image moving_square(int width, int height, int frame) {
  Image image = flat_image(width, height, {60, 60, 60});
  const int left = (frame * 3) % (width - 32);
  for (int y = height / 2 - 16; y < height / 2 + 16; ++y) {
    for (int x = left; x < left + 32; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = 255;
    }
  }
  return image;
}

// Frame i of the colour test: the primaries, white, black and a brown first (where the BT.601
// and BT.709 matrices differ most), then a sweep through the cube.
Rgb frame_colour(int i) {
  const std::array<Rgb, 6> first{
      {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {0, 0, 0}, {200, 120, 40}}};
  if (i < static_cast<int>(first.size())) return first[static_cast<std::size_t>(i)];
  return {static_cast<std::uint8_t>((i * 53) % 256), static_cast<std::uint8_t>((i * 97 + 80) % 256),
          static_cast<std::uint8_t>((i * 151 + 160) % 256)};
}

using testing::sink_error_of;

class Mp4SinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // x264 and the muxer report statistics on stderr; only errors are of interest here.
    previous_log_level_ = av_log_get_level();
    av_log_set_level(AV_LOG_ERROR);
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::path(::testing::TempDir()) / (std::string("rugosim_mp4_")
                                                    .append(info->name())
                                                    .append("_")
                                                    .append(std::to_string(getpid())));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
    av_log_set_level(previous_log_level_);
  }

  std::string file(const std::string& name) const { return (folder_ / name).string(); }

  fs::path folder_;
  int previous_log_level_ = 0;
};

TEST_F(Mp4SinkTest, WritesH264WithTheFrameCountDurationAndColours) {
  constexpr int kWidth = 320;
  constexpr int kHeight = 240;
  constexpr int kFrames = 45;
  constexpr double kFps = 30;
  const std::string path = file("colours.mp4");
  {
    Mp4Sink sink(path, kWidth, kHeight, Mp4Options{.fps = kFps});
    EXPECT_EQ(sink.keyframe_interval(), 30);  // one per second by default
    for (int i = 0; i < kFrames; ++i) {
      sink.write(flat_image(kWidth, kHeight, frame_colour(i)), static_cast<std::size_t>(i));
    }
    EXPECT_EQ(sink.frames_written(), std::size_t{kFrames});
    sink.close();
    sink.close();  // idempotent
  }

  const testing::VideoProbe probe = testing::probe_video(path, /*decode_pixels=*/true);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.width, kWidth);
  EXPECT_EQ(probe.height, kHeight);
  EXPECT_EQ(probe.frames, std::size_t{kFrames});
  EXPECT_NEAR(probe.fps, kFps, 1e-9);
  EXPECT_NEAR(probe.duration_s, kFrames / kFps, 1 / kFps);
  ASSERT_EQ(probe.decoded_rgba.size(), std::size_t{kFrames});

  // Every frame comes back in order and in its colour: RGB → BT.709 limited-range YUV →
  // RGB loses at most rounding and the encoder's quantisation (crf 18 on a flat frame). With
  // a BT.601 matrix on either side, pure red would come back off by tens of levels.
  constexpr int kTolerance = 6;  // levels of 255
  constexpr int kMargin = 8;     // px, away from the edges
  for (int i = 0; i < kFrames; ++i) {
    const Image& decoded = probe.decoded_rgba[static_cast<std::size_t>(i)];
    const Rgb expected = frame_colour(i);
    int worst = 0;
    for (int y = kMargin; y < kHeight - kMargin; ++y) {
      for (int x = kMargin; x < kWidth - kMargin; ++x) {
        for (std::size_t c = 0; c < 3; ++c) {
          worst = std::max(worst, std::abs(decoded.pixel(x, y)[c] - expected[c]));
        }
      }
    }
    EXPECT_LE(worst, kTolerance) << "frame " << i << ", colour " << int{expected[0]} << ","
                                 << int{expected[1]} << "," << int{expected[2]};
  }
}

TEST_F(Mp4SinkTest, TimestampsAreConsecutiveWhateverTheIndices) {
  const std::string path = file("gaps.mp4");
  Mp4Sink sink(path, 64, 48, Mp4Options{.fps = 25, .preset = "ultrafast"});
  for (const std::size_t index : {7U, 8U, 20U, 21U, 500U}) {
    sink.write(moving_square(64, 48, static_cast<int>(index)), index);
  }
  sink.close();
  const testing::VideoProbe probe = testing::probe_video(path);
  EXPECT_EQ(probe.frames, 5U);
  EXPECT_NEAR(probe.duration_s, 5 / 25.0, 1 / 25.0);
}

// A frame numbered with the picture of the frame before is not converted again, and the clip
// is byte for byte the clip of converting every frame; a frame with another number (or none)
// is converted.
TEST_F(Mp4SinkTest, RepeatedPicturesAreEncodedAsIfConvertedAgain) {
  auto encode = [&](const std::string& name, bool numbered) {
    const std::string path = file(name);
    Mp4Sink sink(path, 64, 48, Mp4Options{.fps = 25, .preset = "ultrafast"});
    std::uint64_t number = 100;
    for (int i = 0; i < 40; ++i) {
      const int step = i < 10 ? i : (i < 30 ? 10 : i);  // moving, at rest for 20 frames, moving
      Image image = moving_square(64, 48, step);
      if (numbered) image.picture = step == 10 ? 77 : ++number;
      sink.write(image, static_cast<std::size_t>(i));
    }
    sink.close();
    return path;
  };
  const std::string numbered = encode("numbered.mp4", true);
  const std::string plain = encode("plain.mp4", false);
  EXPECT_EQ(testing::probe_video(numbered).frames, 40u);
  const std::string bytes_a = testing::read_text(numbered);
  const std::string bytes_b = testing::read_text(plain);
  EXPECT_FALSE(bytes_a.empty());
  EXPECT_EQ(bytes_a, bytes_b);
}

TEST_F(Mp4SinkTest, KilledRenderLeavesEveryCompletedFragment) {
  // The child renders 100 frames with a keyframe every 10 and is SIGKILLed before close():
  // no trailer, no encoder flush, destructors never run. Keyframes fall on frames 0, 10, ...,
  // 90; the muxer closes the fragment [k, k + 10) when the packet of keyframe k + 10 arrives,
  // and the sink flushes it to the file right then. With "ultrafast" (no lookahead, no
  // B-frames) and one thread, x264 returns each frame's packet as soon as the frame is sent,
  // so after frame 99 the fragments up to frame 89 are on disk and only the open fragment
  // [90, 100) is lost: at least kFrames - kKeyframeInterval = 90 frames survive (more only if
  // x264 put in an extra scene-cut keyframe, which cuts a fragment early), and nothing is
  // invented (<= 100). A slower preset or more threads also keep frames inside the encoder
  // (lookahead, B-frames, about one per frame thread), which delays the keyframe packets: with
  // the default "medium" the same render keeps 80 frames here.
  constexpr int kFrames = 100;
  constexpr int kKeyframeInterval = 10;
  constexpr int kWidth = 320;
  constexpr int kHeight = 240;
  const std::string path = file("killed.mp4");
  const pid_t child = fork();
  ASSERT_NE(child, -1) << "fork failed";
  if (child == 0) {
    // Never returns into GoogleTest: ends by SIGKILL, or _exit on an unexpected error.
    try {
      Mp4Sink sink(
          path, kWidth, kHeight,
          Mp4Options{.preset = "ultrafast", .keyframe_interval = kKeyframeInterval, .threads = 1});
      for (int i = 0; i < kFrames; ++i) {
        sink.write(moving_square(kWidth, kHeight, i), static_cast<std::size_t>(i));
      }
      raise(SIGKILL);
    } catch (...) {
      _exit(3);
    }
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGKILL);

  const testing::VideoProbe probe = testing::probe_video(path);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.width, kWidth);
  EXPECT_EQ(probe.height, kHeight);
  EXPECT_GE(probe.frames, std::size_t{kFrames - kKeyframeInterval});
  EXPECT_LE(probe.frames, std::size_t{kFrames});
  RecordProperty("frames_after_sigkill", static_cast<int>(probe.frames));
}

// What a kill in the middle of a write leaves: the file cut at any byte after its first
// fragment. Every fragment wholly before the cut must decode; the fragment the cut falls in
// may give some of its samples, never a decoding error. A cut inside the first fragment
// leaves nothing to play and is not tried; one inside the moof box of one of the next few
// fragments (a few hundred bytes each) may leave a file libavformat refuses to open, as it
// reads those boxes while opening (ffprobe refuses it too). (The kill test above stops the
// writer between fragments; a real kill can land inside one, since a fragment takes several
// write calls.)
TEST_F(Mp4SinkTest, AFileCutAtAnyByteKeepsEveryFragmentBeforeTheCut) {
  constexpr int kFrames = 60;
  constexpr int kKeyframeInterval = 10;
  const std::string path = file("whole.mp4");
  {
    Mp4Sink sink(
        path, 160, 120,
        Mp4Options{.preset = "ultrafast", .keyframe_interval = kKeyframeInterval, .threads = 1});
    for (int i = 0; i < kFrames; ++i) {
      sink.write(moving_square(160, 120, i), static_cast<std::size_t>(i));
    }
    sink.close();
  }
  const std::string bytes = testing::read_text(path);
  // Where each fragment's boxes start (a box's type follows its 4-byte size).
  auto boxes = [&](const char* type) {
    std::vector<std::size_t> starts;
    for (std::size_t at = bytes.find(type); at != std::string::npos;
         at = bytes.find(type, at + 4)) {
      starts.push_back(at - 4);
    }
    return starts;
  };
  const std::vector<std::size_t> moofs = boxes("moof");
  const std::vector<std::size_t> mdats = boxes("mdat");
  ASSERT_EQ(moofs.size(), std::size_t{kFrames / kKeyframeInterval});
  ASSERT_EQ(mdats.size(), moofs.size());

  // Cuts spread through the file from the second fragment on, plus one at each box's start.
  std::vector<std::size_t> cuts;
  constexpr std::size_t kCuts = 90;
  for (std::size_t i = 0; i <= kCuts; ++i) {
    cuts.push_back(moofs[1] + (bytes.size() - moofs[1]) * i / kCuts);
  }
  cuts.insert(cuts.end(), moofs.begin() + 1, moofs.end());
  cuts.insert(cuts.end(), mdats.begin() + 1, mdats.end());
  std::sort(cuts.begin(), cuts.end());

  const std::string cut_path = file("cut.mp4");
  std::size_t previous_frames = 0;
  for (const std::size_t cut : cuts) {
    {
      std::ofstream out(cut_path, std::ios::binary | std::ios::trunc);
      out.write(bytes.data(), static_cast<std::streamsize>(cut));
    }
    const auto whole_fragments = static_cast<std::size_t>(
        std::count_if(moofs.begin() + 1, moofs.end(), [&](std::size_t m) { return m <= cut; }));
    bool inside_a_moof = false;
    for (std::size_t k = 0; k < moofs.size(); ++k) {
      inside_a_moof = inside_a_moof || (moofs[k] < cut && cut < mdats[k]);
    }
    testing::VideoProbe probe;
    try {
      probe = testing::probe_video(cut_path, false, testing::FileEnd::may_be_cut);
    } catch (const std::runtime_error& error) {
      // libavformat reads the first few moof boxes while it opens the file, and refuses a
      // file that ends inside one.
      if (inside_a_moof) continue;
      ADD_FAILURE() << "cut at byte " << cut << " of " << bytes.size()
                    << ", inside a sample: " << error.what();
      continue;
    }
    EXPECT_GE(probe.frames, whole_fragments * kKeyframeInterval) << "cut at byte " << cut;
    EXPECT_LE(probe.frames, (whole_fragments + 1) * kKeyframeInterval) << "cut at byte " << cut;
    EXPECT_GE(probe.frames, previous_frames) << "cut at byte " << cut;
    previous_frames = probe.frames;
  }
  EXPECT_EQ(previous_frames, std::size_t{kFrames});
}

TEST_F(Mp4SinkTest, FullDeviceIsASinkErrorNamingThePathAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const std::string message = sink_error_of([] {
    Mp4Sink sink("/dev/full", 64, 48, Mp4Options{.preset = "ultrafast"});
    for (int i = 0; i < 60; ++i)
      sink.write(moving_square(64, 48, i), static_cast<std::size_t>(i));
    sink.close();
  });
  EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
  EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
}

// A disk that fills up in the middle of a render (a file size limit stands in for it): the
// header goes through, a later fragment does not, and the write or the close that hits it
// says so with the path; close() ends it all the same and frees everything (LeakSanitizer).
TEST_F(Mp4SinkTest, DiskFullMidRenderIsASinkErrorFromWriteOrClose) {
  const std::string path = file("limited.mp4");
  const testing::FileSizeLimit limit(16 * 1024);  // bytes: the header and a few fragments of noise
  std::string message;
  {
    Mp4Sink sink(path, 160, 120,
                 Mp4Options{.crf = 0, .preset = "ultrafast", .keyframe_interval = 2});
    message = testing::sink_error_writing_noise(sink, 160, 120, 100);
  }
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
}

TEST_F(Mp4SinkTest, MissingDirectoryFailsAtConstructionNamingThePath) {
  const std::string path = file("no_such_folder/clip.mp4");
  const std::string message = sink_error_of([&] { Mp4Sink sink(path, 64, 48); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(Mp4SinkTest, PathIsAFileEvenWithAColon) {
  const std::string path = file("take:1.mp4");  // FFmpeg would read "take:" as a protocol
  Mp4Sink sink(path, 64, 48, Mp4Options{.preset = "ultrafast"});
  sink.write(moving_square(64, 48, 0), 0);
  sink.close();
  EXPECT_EQ(testing::probe_video(path).frames, 1U);
}

TEST_F(Mp4SinkTest, BadOptionsAndSizesAreInvalidArguments) {
  const std::string path = file("bad.mp4");
  auto make = [&](int width, int height, const Mp4Options& options) {
    Mp4Sink sink(path, width, height, options);
  };
  EXPECT_THROW(make(64, 48, Mp4Options{.crf = -1}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.crf = 52}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.preset = "turbo"}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.fps = 0}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.fps = -30}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.keyframe_interval = -1}), std::invalid_argument);
  EXPECT_THROW(make(64, 48, Mp4Options{.threads = -2}), std::invalid_argument);
  EXPECT_THROW(make(0, 48, Mp4Options{}), std::invalid_argument);
  try {
    make(321, 240, Mp4Options{});
    ADD_FAILURE() << "an odd width was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "MP4 needs an even width and height, got 321x240");
  }
  EXPECT_THROW(make(320, 241, Mp4Options{}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));  // nothing opened before the checks

  EXPECT_TRUE(mp4_preset_is_valid("veryslow"));
  EXPECT_FALSE(mp4_preset_is_valid("Medium"));
  EXPECT_TRUE(mp4_crf_is_valid(0));
  EXPECT_TRUE(mp4_crf_is_valid(51));
}

TEST_F(Mp4SinkTest, FrameOfAnotherSizeAndWriteAfterCloseAreSinkErrors) {
  const std::string path = file("sizes.mp4");
  Mp4Sink sink(path, 64, 48, Mp4Options{.preset = "ultrafast"});
  sink.write(moving_square(64, 48, 0), 0);
  const std::string wrong_size = sink_error_of([&] { sink.write(Image(64, 50), 1); });
  EXPECT_NE(wrong_size.find(path), std::string::npos) << wrong_size;
  EXPECT_NE(wrong_size.find("64x50"), std::string::npos) << wrong_size;
  Image short_buffer(64, 48);
  short_buffer.rgba.resize(100);
  sink_error_of([&] { sink.write(short_buffer, 1); });
  EXPECT_EQ(sink.frames_written(), 1U);

  sink.close();
  sink_error_of([&] { sink.write(moving_square(64, 48, 1), 1); });
  EXPECT_EQ(testing::probe_video(path).frames, 1U);
}

}  // namespace
}  // namespace rugosim
