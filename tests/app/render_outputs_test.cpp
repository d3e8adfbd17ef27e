// `rugosim render` to the outputs chosen by OUT's extension besides MP4 and PNG sequences
// (INTERFACE.md, "Command line"): a GIF clip decoded by libavformat/libavcodec and compared with
// the PNG frames, a still equal to the same frame of a sequence, and the usage errors that keep
// a file from holding another format than its name says.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/app/command_line.h"
#include "render/image.h"
#include "render/sinks/png_io.h"
#include "render/text/frame_text.h"
#include "support/file_text.h"
#include "support/render_command_fixture.h"
#include "support/video_probe.h"
#include "support/webp_probe.h"

namespace {

namespace fs = std::filesystem;
using rugosim::Image;
using rugosim::read_png_file;
using rugosim::testing::figure12a;
using rugosim::testing::listing;
using rugosim::testing::Outcome;
using rugosim::testing::probe_video;
using rugosim::testing::read_text;
using rugosim::testing::RenderCommand;
using rugosim::testing::VideoProbe;

// How far a GIF frame (256 colours, dithered) is from the RGB frame it was made of: colour
// only, "far" past 48 levels.
rugosim::testing::ImageDifference palette_error(const Image& gif, const Image& png) {
  return rugosim::testing::image_difference(gif, png, 3, 48);
}

TEST_F(RenderCommand, GifHoldsTheFramesAtTheClipsRateInItsPalette) {
  const fs::path scene = fixed_camera_scene();
  const std::string gif = (dir_ / "out" / "clip.gif").string();
  const Outcome r = run({scene.string(), "-o", gif, "--frames", "0:30", "--size", "320x180"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("done: 31 frames written to"), std::string::npos) << r.err;
  const VideoProbe probe = probe_video(gif, true);
  EXPECT_EQ(probe.codec, "gif");
  EXPECT_EQ(probe.width, 320);
  EXPECT_EQ(probe.height, 180);
  ASSERT_EQ(probe.frames, 31u);
  // Whole-centisecond delays (3 and 4 at 30 fps) keep the clip's length within one.
  EXPECT_NEAR(probe.duration_s, 31.0 / 30.0, 0.01 + 1e-9);
  // Stated tolerance: one palette for the clip with error diffusion; the scene has a few flat
  // fills and anti-aliased edges, so on average a channel is within 1 level (measured: 0.11)
  // and at most 0.2% of the pixels (edge pixels) are more than 48 levels off (measured: none).
  for (const std::size_t k : {0u, 15u, 30u}) {
    const Image png = frame(scene.string(), k, {});
    ASSERT_FALSE(png.rgba.empty());
    const rugosim::testing::ImageDifference e = palette_error(probe.decoded_rgba[k], png);
    EXPECT_LT(e.mean, 1.0) << "frame " << k;
    EXPECT_LT(e.far_share, 0.002) << "frame " << k;
    std::printf("frame %zu: mean %.3f levels, %.4f%% of pixels past 48\n", k, e.mean,
                100.0 * e.far_share);
  }
}

TEST_F(RenderCommand, StillIsTheSameFrameAsInASequence) {
  const fs::path scene = fixed_camera_scene();
  const std::string still = (dir_ / "out" / "still.png").string();
  const Outcome r = run({scene.string(), "-o", still, "--frame", "45", "--size", "320x180"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("done: 1 frame written to"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"still.png"});
  const Image from_sequence = frame(scene.string(), 45, {});
  EXPECT_EQ(rugosim::testing::differing_pixels(read_png_file(still), from_sequence), 0u);
}

TEST_F(RenderCommand, StillAndGifAreKeptWithoutYAndReplacedWithIt) {
  const fs::path scene = fixed_camera_scene();
  for (const std::string name : {"still.png", "clip.gif"}) {
    const std::string out = (dir_ / "out" / name).string();
    rugosim::testing::write_text(out, "earlier");
    // A still of frame 2, or a clip of frames 0 to 2.
    std::vector<std::string> used = {scene.string(), "-o", out, "--size", "64x36"};
    const std::vector<std::string> which = name == "still.png"
                                               ? std::vector<std::string>{"--frame", "2"}
                                               : std::vector<std::string>{"--frames", "0:2"};
    used.insert(used.end(), which.begin(), which.end());
    Outcome r = run(used);
    EXPECT_EQ(r.code, 2) << name << "\n" << r.err;
    EXPECT_NE(r.err.find("add -y"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(out), "earlier");
    std::vector<std::string> forced = used;
    forced.push_back("-y");
    r = run(forced);
    EXPECT_EQ(r.code, 0) << name << "\n" << r.err;
    EXPECT_NE(read_text(out), "earlier");
  }
  EXPECT_EQ(listing(dir_ / "out"), (std::vector<std::string>{"clip.gif", "still.png"}));
}

// --roughness-scale and render.roughness_scale: 0 draws smooth outlines, a larger scale changes
// more pixels, the option and the key give the same frame; the simulation never sees them (the
// same trajectory with and without the key).
TEST_F(RenderCommand, RoughnessScaleChangesTheDrawingAndNotTheSimulation) {
  const fs::path scene = fixed_camera_scene();
  const Image smooth = frame(scene.string(), 30, {"--roughness-scale", "0"});
  const Image normal = frame(scene.string(), 30, {});
  const Image rough = frame(scene.string(), 30, {"--roughness-scale", "3"});
  const std::size_t changed = rugosim::testing::differing_pixels(smooth, normal);
  EXPECT_GT(changed, 100u);
  EXPECT_GT(rugosim::testing::differing_pixels(smooth, rough), changed);
  const fs::path keyed = fixed_camera_scene(R"([], "roughness_scale": 3)");
  EXPECT_EQ(rugosim::testing::differing_pixels(frame(keyed.string(), 30, {}), rough), 0u);

  std::vector<std::string> trajectories;
  for (const fs::path& s : {scene, keyed}) {
    const fs::path csv = dir_ / (s.stem().string() + ".csv");
    const auto r =
        rugosim::testing::run_command_line(rugosim::testing::program() + " simulate " + s.string() +
                                               " --duration 0.5 --trajectory " + csv.string(),
                                           dir_ / "simulate.err");
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    trajectories.push_back(read_text(csv));
  }
  EXPECT_FALSE(trajectories[0].empty());
  EXPECT_EQ(trajectories[0], trajectories[1]);
}

TEST_F(RenderCommand, OutputsThatWouldHoldAnotherFormatThanTheirNameExit2AndWriteNothing) {
  const std::string out = (dir_ / "out").string();
  expect_usage_errors({
      {{figure12a(), "-o", out + "/strip.mp4", "--strip", "4"}, "must end in .png"},
      {{figure12a(), "-o", out + "/strip.png", "--strip", "4", "--format", "mp4"},
       "the name says png"},
      {{figure12a(), "-o", out + "/x.gif", "--format", "png", "--frame", "1"}, "the name says gif"},
      {{figure12a(), "-o", out + "/x.png"}, "add --frame K"},
      {{figure12a(), "-o", out + "/x.png", "--frame", "151"}, "last frame is 150"},
      {{figure12a(), "-o", out + "/x.png", "--frame", "-1"}, "--frame"},
      {{figure12a(), "-o", out + "/x.png", "--frame", "5", "--frames", "0:9"}, "give one"},
      {{figure12a(), "-o", out + "/x.png", "--frame", "2", "--strip", "3"}, "give one"},
      {{figure12a(), "-o", out + "/x.mp4", "--frame", "3"}, "not a clip"},
      {{figure12a(), "-o", out + "/x.webm", "--frame", "3"}, "not a clip"},
      {{figure12a(), "-o", out + "/f_%d.png", "--frame", "3"}, "without %d"},
      {{figure12a(), "-o", out + "/x.gif", "--fps", "60"}, "at most 50 frames per second"},
      {{figure12a(), "-o", out + "/x.avi"}, "cannot tell the output format"},
      {{figure12a(), "-o", out + "/x.mov", "--format", "webm"}, "the name says mov"},
  });
}

// figure12a with a fixed camera and render.background "transparent" (fixed_camera_scene's
// overlays text is spliced in after "overlays": as it is).
class RenderTransparent : public RenderCommand, public ::testing::WithParamInterface<std::string> {
 protected:
  fs::path scene() { return fixed_camera_scene(R"([], "background": "transparent")"); }
};

TEST_F(RenderCommand, TransparentStillHasAlphaWhereNoBodyIsAndMp4IsRefused) {
  // Spliced in after "overlays": (fixed_camera_scene).
  const fs::path scene = fixed_camera_scene(R"([], "background": "transparent")");
  const std::string still = (dir_ / "out" / "still.png").string();
  Outcome r = run({scene.string(), "-o", still, "--frame", "30", "--size", "320x180"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Image image = read_png_file(still);
  ASSERT_EQ(image.width, 320);
  std::size_t clear = 0, opaque = 0, between = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
    clear += image.rgba[i] == 0 ? 1u : 0u;
    opaque += image.rgba[i] == 255 ? 1u : 0u;
    between += image.rgba[i] != 0 && image.rgba[i] != 255 ? 1u : 0u;
  }
  const double pixels = 320.0 * 180.0;
  EXPECT_GT(static_cast<double>(clear) / pixels, 0.5) << "the background is most of the frame";
  EXPECT_GT(static_cast<double>(opaque) / pixels, 0.1) << "the bodies and the container";
  EXPECT_GT(between, 0u) << "anti-aliased edges are partly transparent";
  EXPECT_EQ(image.rgba[3], 0) << "the top left corner is background";
  // The same frame over an opaque background differs only in the background and the edges.
  const Image opaque_frame = frame(fixed_camera_scene().string(), 30, {});
  std::size_t same_opaque = 0;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    if (image.rgba[i + 3] != 255) continue;
    same_opaque += std::equal(image.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                              image.rgba.begin() + static_cast<std::ptrdiff_t>(i + 3),
                              opaque_frame.rgba.begin() + static_cast<std::ptrdiff_t>(i))
                       ? 1u
                       : 0u;
  }
  EXPECT_GT(static_cast<double>(same_opaque) / static_cast<double>(opaque), 0.99)
      << "opaque pixels keep their colours";

  r = run({scene.string(), "-o", (dir_ / "out" / "clip.mp4").string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("has no alpha"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "clip.mp4"));
}

TEST_P(RenderTransparent, ClipKeepsTheFramesAndTheirAlpha) {
  const std::string out = (dir_ / "out" / ("clip." + GetParam())).string();
  const Outcome r = run({scene().string(), "-o", out, "--frames", "0:11", "--size", "160x90"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<Image> frames;
  if (GetParam() == "webp") {
    frames = rugosim::testing::probe_webp(out).frames;
  } else {
    const VideoProbe probe = probe_video(out, true);
    EXPECT_EQ(probe.codec, GetParam() == "webm" ? "vp9" : "prores");
    EXPECT_NEAR(probe.duration_s, 12.0 / 30.0, 2e-3);
    frames = probe.decoded_rgba;
  }
  ASSERT_EQ(frames.size(), 12u);
  EXPECT_EQ(frames[0].width, 160);
  EXPECT_EQ(frames[0].height, 90);
  // The decoded frame against the PNG still of the same frame (straight alpha both), stated
  // tolerance: 2 levels on average over every channel (measured: VP9 0.83, ProRes 0.04, WebP
  // 0.57; VP9 and WebP are lossy 4:2:0).
  const std::string still = (dir_ / "out" / "still.png").string();
  ASSERT_EQ(run({scene().string(), "-o", still, "--frame", "6", "--size", "160x90", "-y"}).code, 0);
  const Image png = read_png_file(still);
  double sum = 0.0;
  for (std::size_t i = 0; i < png.rgba.size(); ++i) {
    // Where a pixel is transparent its colour means nothing.
    if (png.rgba[i - i % 4 + 3] == 0 && i % 4 != 3) continue;
    sum += std::abs(int{frames[6].rgba[i]} - int{png.rgba[i]});
  }
  const double mean = sum / static_cast<double>(png.rgba.size());
  EXPECT_LT(mean, 2.0);
  std::printf("%s: mean difference %.3f levels\n", GetParam().c_str(), mean);
  // Alpha: within 8 levels of 0 wherever the still is transparent within 4 px, and of 255
  // wherever it is opaque within 4 px: well away from the anti-aliased edges, beside which
  // VP9's 8×8 transforms ring.
  const int w = png.width;
  int worst_clear = 0, worst_opaque = 255;
  constexpr int kAway = 4;
  for (int y = kAway; y + kAway < png.height; ++y) {
    for (int x = kAway; x + kAway < w; ++x) {
      bool clear = true, opaque = true;
      for (int dy = -kAway; dy <= kAway; ++dy) {
        for (int dx = -kAway; dx <= kAway; ++dx) {
          const std::uint8_t a = png.rgba[4 * static_cast<std::size_t>((y + dy) * w + x + dx) + 3];
          clear = clear && a == 0;
          opaque = opaque && a == 255;
        }
      }
      const int decoded = frames[6].rgba[4 * static_cast<std::size_t>(y * w + x) + 3];
      if (clear) worst_clear = std::max(worst_clear, decoded);
      if (opaque) worst_opaque = std::min(worst_opaque, decoded);
    }
  }
  EXPECT_LE(worst_clear, 8) << GetParam();
  EXPECT_GE(worst_opaque, 247) << GetParam();
  std::printf("%s: alpha at most %d where clear, at least %d where opaque\n", GetParam().c_str(),
              worst_clear, worst_opaque);
}

INSTANTIATE_TEST_SUITE_P(Formats, RenderTransparent, ::testing::Values("webm", "mov", "webp"));

TEST_F(RenderCommand, StripsKeepAtMost4000PxWideAndLayOutAGridWithTimeLabels) {
  const fs::path scene = fixed_camera_scene();
  const std::string wide = (dir_ / "out" / "wide.png").string();
  Outcome r = run({scene.string(), "-o", wide, "--strip", "6"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Image strip = read_png_file(wide);
  EXPECT_LE(strip.width, 4000) << "six 1280x720 frames shrink to fit";
  EXPECT_GT(strip.width, 3900);
  EXPECT_NEAR(static_cast<double>(strip.height), (strip.width / 6.0) * 720.0 / 1280.0, 4.0);

  const std::string plain = (dir_ / "out" / "plain.png").string();
  const std::string labelled = (dir_ / "out" / "labelled.png").string();
  const std::vector<std::string> grid = {"--strip", "6",       "--columns", "3",
                                         "--size",  "320x180", "--gap",     "4"};
  std::vector<std::string> args = {scene.string(), "-o", plain};
  args.insert(args.end(), grid.begin(), grid.end());
  ASSERT_EQ(run(args).code, 0);
  args[2] = labelled;
  args.push_back("--strip-labels");
  ASSERT_EQ(run(args).code, 0);
  const Image a = read_png_file(plain);
  const Image b = read_png_file(labelled);
  EXPECT_EQ(a.width, 3 * 320 + 2 * 4);
  EXPECT_EQ(a.height, 2 * 180 + 4);
  const int band = rugosim::strip_label_band(180);
  ASSERT_EQ(b.height, 2 * (180 + band) + 4);
  // The frames are the same; the bands hold dark text, centred under each frame.
  for (int cell = 0; cell < 6; ++cell) {
    const int x0 = (cell % 3) * 324;
    const int ya = (cell / 3) * 184;
    const int yb = (cell / 3) * (184 + band);
    std::size_t differ = 0;
    for (int y = 0; y < 180; ++y) {
      differ +=
          !std::equal(a.pixel(x0, ya + y), a.pixel(x0, ya + y) + 4 * 320, b.pixel(x0, yb + y));
    }
    EXPECT_EQ(differ, 0u) << "cell " << cell;
    int left = 320, right = -1;
    for (int y = yb + 180; y < yb + 180 + band; ++y) {
      for (int x = 0; x < 320; ++x) {
        if (b.pixel(x0 + x, y)[0] < 128) {
          left = std::min(left, x);
          right = std::max(right, x);
        }
      }
    }
    EXPECT_GE(right, left) << "a label under cell " << cell;
    EXPECT_NEAR((left + right) / 2.0, 160.0, 4.0) << "centred, cell " << cell;
  }
  r = run({scene.string(), "-o", (dir_ / "out" / "x.mp4").string(), "--columns", "3"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("expected --strip N"), std::string::npos) << r.err;
}

TEST(UnknownCommand, SuggestsTheNearestCommandForATypo) {
  const auto c = rugosim::app::make_command_line(1);
  EXPECT_EQ(rugosim::app::unknown_command_error(*c, "simulte"),
            "unknown command \"simulte\"; did you mean \"simulate\"?");
  EXPECT_EQ(rugosim::app::unknown_command_error(*c, "redner"),
            "unknown command \"redner\"; did you mean \"render\"?");
  EXPECT_EQ(rugosim::app::unknown_command_error(*c, "plott"),
            "unknown command \"plott\"; did you mean \"plot\"?");
  EXPECT_EQ(rugosim::app::unknown_command_error(*c, "xyz"),
            "unknown command \"xyz\"; the commands are validate, info, simulate, render, "
            "snapshot, join, plan, sweep, plot");
  for (const std::string known : {"render", "simulate", "--help", "-h", ""})
    EXPECT_EQ(rugosim::app::unknown_command_error(*c, known), "") << known;
}

}  // namespace
