#include "render/sinks/png_sequence_sink.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/sinks/png_io.h"
#include "support/scratch_dir.h"

namespace rugosim {
namespace {

namespace fs = std::filesystem;

// The shared scratch directory, with the sink's file pattern inside it.
class ScratchDirectory : public testing::ScratchDir {
 public:
  ScratchDirectory() : testing::ScratchDir("png_sequence_test") {}
  std::string pattern(const std::string& name) const { return (path() / name).string(); }
};

// An opaque frame that differs from frame to frame: a background colour from the index and a
// random filled rectangle.
Image test_frame(std::size_t index, int width, int height, std::mt19937& rng) {
  Image image(width, height);
  const auto shade = static_cast<std::uint8_t>(index * 11);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = shade;
      p[1] = static_cast<std::uint8_t>(255 - shade);
      p[2] = 40;
      p[3] = 255;
    }
  }
  std::uniform_int_distribution<int> column(0, width - 1);
  std::uniform_int_distribution<int> row(0, height - 1);
  const int x0 = column(rng);
  const int y0 = row(rng);
  for (int y = y0; y < std::min(height, y0 + 12); ++y) {
    for (int x = x0; x < std::min(width, x0 + 20); ++x) {
      image.pixel(x, y)[0] = static_cast<std::uint8_t>(rng());
      image.pixel(x, y)[2] = static_cast<std::uint8_t>(rng());
    }
  }
  return image;
}

TEST(PngPattern, AcceptsOneIntegerConversion) {
  for (const char* good : {"a_%d.png", "b_%05d.png", "100%%_%03d.png", "c_%3d.png", "%d",
                           "out/f_%04d.png", "%12d.png", "%012d.png", "x%%%d%%.png"}) {
    EXPECT_TRUE(is_png_pattern(good)) << good;
  }
  for (const char* bad :
       {"x.png",   "%s.png",  "%d_%d.png", "%.png", "%5",          "%123d", "%0123d",
        "%0d.png", "%00d",    "%05",       "%-3d",  "%+d",         "%ld",   "%u",
        "a%",      "%%d.png", "%%",        "",      "f_%04d.png%", "%x"}) {
    EXPECT_FALSE(is_png_pattern(bad)) << bad;
  }
}

TEST(PngPattern, FormatsLikePrintfWithoutIt) {
  EXPECT_EQ(format_frame_path("a_%d.png", 7), "a_7.png");
  EXPECT_EQ(format_frame_path("b_%05d.png", 42), "b_00042.png");
  EXPECT_EQ(format_frame_path("100%%_%03d.png", 7), "100%_007.png");
  EXPECT_EQ(format_frame_path("c_%3d.png", 5), "c_  5.png");
  EXPECT_EQ(format_frame_path("out/f_%04d.png", 0), "out/f_0000.png");
  // Never truncated, even past int.
  EXPECT_EQ(format_frame_path("f_%02d", 12345), "f_12345");
  EXPECT_EQ(format_frame_path("f_%d", 10000000000u), "f_10000000000");
  EXPECT_EQ(format_frame_path("%%%d%%", 3), "%3%");
  EXPECT_THROW(format_frame_path("x.png", 1), std::invalid_argument);
  EXPECT_THROW(format_frame_path("%s_%d.png", 1), std::invalid_argument);
}

TEST(PngSequenceSink, ConstructorRejectsBadPatternsSaysWhatIsExpected) {
  const ScratchDirectory directory;
  for (const char* bad : {"x.png", "%s.png", "%d_%d.png", "%.png", "%5", "%123d"}) {
    try {
      PngSequenceSink sink(directory.pattern(bad));
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(bad), std::string::npos) << message;
      EXPECT_NE(message.find("%04d"), std::string::npos) << message;
    }
  }
  // The frame number belongs in the file name.
  EXPECT_THROW(PngSequenceSink(directory.pattern("run_%02d/f.png")), std::invalid_argument);
  EXPECT_THROW(PngSequenceSink(directory.pattern("f_%d.png"), PngSettings{}, 0),
               std::invalid_argument);
  // Good ones construct (and write nothing).
  for (const char* good : {"a_%d.png", "b_%05d.png", "100%%_%03d.png"}) {
    EXPECT_NO_THROW(PngSequenceSink(directory.pattern(good))) << good;
  }
  EXPECT_TRUE(directory.listing().empty());
}

TEST(PngSequenceSink, MissingDirectoryIsASinkError) {
  const ScratchDirectory directory;
  const std::string missing = (directory.path() / "nope").string();
  try {
    PngSequenceSink sink(missing + "/f_%04d.png");
    ADD_FAILURE() << "a missing directory was accepted";
  } catch (const SinkError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(missing), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  // A pattern without a directory writes into the working directory, which exists.
  EXPECT_NO_THROW(PngSequenceSink("f_%04d.png"));
}

TEST(PngSequenceSink, WritesEveryFrameOnTwoWorkers) {
  const ScratchDirectory directory;
  std::mt19937 rng(21);
  std::vector<Image> frames;
  for (std::size_t k = 3; k <= 22; ++k)
    frames.push_back(test_frame(k, 64, 48, rng));
  {
    PngSequenceSink sink(directory.pattern("f_%04d.png"), PngSettings{}, 2);
    for (std::size_t k = 3; k <= 22; ++k)
      sink.write(frames[k - 3], k);
    sink.close();
    EXPECT_EQ(sink.frames_written(), 20u);
    EXPECT_NO_THROW(sink.close());  // idempotent
    EXPECT_THROW(sink.write(frames[0], 23), SinkError);
  }
  std::vector<std::string> expected_names;
  for (std::size_t k = 3; k <= 22; ++k)
    expected_names.push_back(format_frame_path("f_%04d.png", k));
  EXPECT_EQ(directory.listing(), expected_names);  // and no temporary file left
  for (std::size_t k = 3; k <= 22; ++k) {
    const Image read = read_png_file((directory.path() / expected_names[k - 3]).string());
    EXPECT_EQ(read.width, 64);
    EXPECT_EQ(read.height, 48);
    EXPECT_TRUE(read.rgba == frames[k - 3].rgba) << "frame " << k;
  }
}

TEST(PngSequenceSink, DestructorFinishesQueuedFrames) {
  const ScratchDirectory directory;
  std::mt19937 rng(22);
  const Image frame = test_frame(1, 32, 32, rng);
  {
    PngSequenceSink sink(directory.pattern("g_%d.png"), PngSettings{}, 3);
    for (std::size_t k = 0; k < 5; ++k)
      sink.write(frame, k);
  }
  EXPECT_EQ(directory.listing(),
            (std::vector<std::string>{"g_0.png", "g_1.png", "g_2.png", "g_3.png", "g_4.png"}));
}

TEST(PngSequenceSink, RejectsMalformedFrames) {
  const ScratchDirectory directory;
  PngSequenceSink sink(directory.pattern("h_%d.png"));
  Image bad(4, 4);
  bad.rgba.resize(10);
  EXPECT_THROW(sink.write(bad, 0), std::invalid_argument);
  EXPECT_THROW(sink.write(Image{}, 0), std::invalid_argument);
  sink.close();
  EXPECT_EQ(sink.frames_written(), 0u);
}

// Collects the SinkError messages of writing `count` frames and closing.
std::vector<std::string> write_and_close(PngSequenceSink& sink, const Image& frame,
                                         std::size_t count) {
  std::vector<std::string> errors;
  for (std::size_t k = 0; k < count; ++k) {
    try {
      sink.write(frame, k);
    } catch (const SinkError& error) {
      errors.emplace_back(error.what());
    }
  }
  try {
    sink.close();
  } catch (const SinkError& error) {
    errors.emplace_back(error.what());
  }
  return errors;
}

TEST(PngSequenceSink, WorkerFailureSurfacesFromWriteOrClose) {
  // The directory vanishes after the sink checked it: every file creation fails on a worker.
  // (Permissions would not do: the tests may run as root.)
  const ScratchDirectory directory;
  const fs::path gone = directory.path() / "gone";
  fs::create_directory(gone);
  std::mt19937 rng(23);
  const Image frame = test_frame(2, 40, 30, rng);
  PngSequenceSink sink((gone / "f_%03d.png").string(), PngSettings{}, 2);
  fs::remove(gone);
  const std::vector<std::string> errors = write_and_close(sink, frame, 10);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors.back().find((gone / "f_").string()), std::string::npos) << errors.back();
  EXPECT_NE(errors.back().find("No such file or directory"), std::string::npos) << errors.back();
  EXPECT_EQ(sink.frames_written(), 0u);
  // Once failed, the sink stays failed.
  EXPECT_THROW(sink.close(), SinkError);
}

TEST(PngSequenceSink, OneBadFileStopsTheSequence) {
  // A directory where frame 1's file should go: that file cannot be written.
  const ScratchDirectory directory;
  fs::create_directory(directory.path() / "f_1.png");
  std::mt19937 rng(24);
  const Image frame = test_frame(3, 16, 16, rng);
  PngSequenceSink sink(directory.pattern("f_%d.png"), PngSettings{}, 1);
  const std::vector<std::string> errors = write_and_close(sink, frame, 6);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors.back().find("f_1.png"), std::string::npos) << errors.back();
  EXPECT_NE(errors.back().find("Is a directory"), std::string::npos) << errors.back();
  EXPECT_LT(sink.frames_written(), 6u);
}

}  // namespace
}  // namespace rugosim
