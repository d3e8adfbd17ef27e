// `rugosim render` through the program (INTERFACE.md, "Command line"): the three kinds of output
// (MP4, PNG sequence, film strip) decoded independently, identical pixels from both GL backends
// and from a re-run, refusal to overwrite, usage errors that write nothing, I/O failures, and
// what Ctrl-C and SIGKILL leave behind.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <signal.h>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/sinks/png_io.h"
#include "support/file_text.h"
#include "support/program_under_test.h"
#include "support/render_command_fixture.h"
#include "support/video_probe.h"

namespace {

namespace fs = std::filesystem;
using rugosim::Image;
using rugosim::read_png_file;
using rugosim::testing::FileEnd;
using rugosim::testing::probe_video;
using rugosim::testing::VideoProbe;

using rugosim::testing::program;
using rugosim::testing::source_dir;

using rugosim::testing::differing_pixels;
using rugosim::testing::figure12a;
using rugosim::testing::frames_interrupted;
using rugosim::testing::frames_reported;
using rugosim::testing::listing;
using rugosim::testing::Outcome;
using rugosim::testing::read_text;
using rugosim::testing::RenderCommand;
using rugosim::testing::wait_for;
using rugosim::testing::write_text;

TEST_F(RenderCommand, Mp4HoldsTheRequestedFramesAsH264) {
  const fs::path clip = dir_ / "out" / "clip.mp4";
  const Outcome r =
      run({figure12a(), "-o", clip.string(), "--frames", "0:29", "--size", "320x180"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(std::string("30 frames written to ").append(clip.string())),
            std::string::npos)
      << r.err;
  const VideoProbe probe = probe_video(clip.string());
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.width, 320);
  EXPECT_EQ(probe.height, 180);
  EXPECT_EQ(probe.frames, 30u);
  EXPECT_NEAR(probe.duration_s, 1.0, 1.0 / 30.0);
  EXPECT_NEAR(probe.fps, 30.0, 1e-6);
  EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"clip.mp4"});
}

TEST_F(RenderCommand, PngSequenceWritesExactlyTheRequestedFrames) {
  const fs::path out = dir_ / "out";
  const Outcome r = run(
      {figure12a(), "-o", (out / "f_%04d.png").string(), "--frames", "5:9", "--size", "320x180"});
  ASSERT_EQ(r.code, 0) << r.err;
  // Nothing else: no temporary file left beside the frames.
  ASSERT_EQ(listing(out), (std::vector<std::string>{"f_0005.png", "f_0006.png", "f_0007.png",
                                                    "f_0008.png", "f_0009.png"}));
  std::vector<Image> frames;
  for (const std::string& name : listing(out)) {
    frames.push_back(read_png_file((out / name).string()));
    EXPECT_EQ(frames.back().width, 320) << name;
    EXPECT_EQ(frames.back().height, 180) << name;
  }
  // The rocks fall and spin: each frame differs from the one before.
  for (std::size_t i = 1; i < frames.size(); ++i)
    EXPECT_GT(differing_pixels(frames[i - 1], frames[i]), 0u)
        << "frames " << i + 4 << ", " << i + 5;
}

// Panel `k` of a film strip of `width` x `height` frames with gaps of `gap` px.
Image strip_panel(const Image& strip, int k, int width, int height, int gap) {
  Image part(width, height);
  for (int y = 0; y < height; ++y)
    std::copy_n(strip.pixel(k * (width + gap), y), static_cast<std::size_t>(width) * 4,
                part.pixel(0, y));
  return part;
}

Image frame_file(const fs::path& dir, std::size_t index) {
  return read_png_file(
      (dir / std::string("f_").append(std::to_string(index)).append(".png")).string());
}

// Four frames spread over 0..29 (0, 10, 19, 29), with white gaps of max(2, 160 / 160) = 2 px
// between them. The first two are the frames 0 and 10 of the PNG sequence (the frames after
// them: AFrameDoesNotDependOnTheOtherFramesRendered).
TEST_F(RenderCommand, StripPutsTheFramesSideBySideWithGaps) {
  const fs::path scene = fixed_camera_scene();
  ASSERT_FALSE(scene.empty());
  const fs::path strip_file = dir_ / "out" / "strip.png";
  const Outcome r = run({scene.string(), "-o", strip_file.string(), "--strip", "4", "--size",
                         "160x90", "--frames", "0:29"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"strip.png"});
  const Image strip = read_png_file(strip_file.string());
  ASSERT_EQ(strip.width, 4 * 160 + 3 * 2);
  ASSERT_EQ(strip.height, 90);
  for (int gap = 0; gap < 3; ++gap) {
    for (int x = gap * 162 + 160; x < gap * 162 + 162; ++x) {
      for (int y = 0; y < 90; ++y) {
        const std::uint8_t* p = strip.pixel(x, y);
        ASSERT_TRUE(p[0] == 255 && p[1] == 255 && p[2] == 255) << "gap pixel " << x << ", " << y;
      }
    }
  }
  std::vector<Image> panels;
  for (int k = 0; k < 4; ++k)
    panels.push_back(strip_panel(strip, k, 160, 90, 2));
  for (std::size_t k = 1; k < panels.size(); ++k)
    EXPECT_GT(differing_pixels(panels[k - 1], panels[k]), 0u) << "panels " << k - 1 << ", " << k;

  const fs::path frames = dir_ / "frames";
  fs::create_directories(frames);
  const Outcome seq = run({scene.string(), "-o", (frames / "f_%d.png").string(), "--size", "160x90",
                           "--frames", "0:29"});
  ASSERT_EQ(seq.code, 0) << seq.err;
  EXPECT_EQ(differing_pixels(panels[0], frame_file(frames, 0)), 0u);
  EXPECT_EQ(differing_pixels(panels[1], frame_file(frames, 10)), 0u);
}

// Frame k is the state at t = k / fps (INTERFACE.md) whatever else is rendered: the frames of a
// clip rendered in pieces (--frames 0:19, then 20:29) or picked for a strip are the frames of the
// whole clip. The rocks collide from about frame 11 on, so any dependence on the simulation's
// stops shows.
TEST_F(RenderCommand, AFrameDoesNotDependOnTheOtherFramesRendered) {
  const fs::path scene = fixed_camera_scene();
  ASSERT_FALSE(scene.empty());
  const fs::path whole = dir_ / "whole";
  const fs::path piece = dir_ / "piece";
  fs::create_directories(whole);
  fs::create_directories(piece);
  const Outcome all = run({scene.string(), "-o", (whole / "f_%d.png").string(), "--size", "160x90",
                           "--frames", "0:29"});
  ASSERT_EQ(all.code, 0) << all.err;
  const Outcome part = run({scene.string(), "-o", (piece / "f_%d.png").string(), "--size", "160x90",
                            "--frames", "20:29"});
  ASSERT_EQ(part.code, 0) << part.err;
  std::string differ;
  for (std::size_t k = 20; k <= 29; ++k) {
    if (differing_pixels(frame_file(whole, k), frame_file(piece, k)) != 0)
      differ.append(" ").append(std::to_string(k));
  }
  EXPECT_EQ(differ, "") << "frames of --frames 20:29 that differ from the same frames of 0:29";
  const fs::path strip_file = dir_ / "out" / "strip.png";
  const Outcome r = run({scene.string(), "-o", strip_file.string(), "--strip", "4", "--size",
                         "160x90", "--frames", "0:29"});
  ASSERT_EQ(r.code, 0) << r.err;
  const Image strip = read_png_file(strip_file.string());
  const std::size_t indices[] = {0, 10, 19, 29};
  differ.clear();
  for (int k = 0; k < 4; ++k) {
    if (differing_pixels(strip_panel(strip, k, 160, 90, 2), frame_file(whole, indices[k])) != 0)
      differ.append(" ").append(std::to_string(indices[k]));
  }
  EXPECT_EQ(differ, "") << "frames of the strip that differ from the same frames of the clip";
}

TEST_F(RenderCommand, BothBackendsDrawTheSamePixels) {
  std::vector<Image> by_backend[2];
  const char* backends[] = {"osmesa", "egl"};
  for (int b = 0; b < 2; ++b) {
    const fs::path out = dir_ / "out" / backends[b];
    fs::create_directories(out);
    const Outcome r = run({figure12a(), "-o", (out / "f_%d.png").string(), "--frames", "20:22",
                           "--size", "320x180", "--backend", backends[b]});
    ASSERT_EQ(r.code, 0) << backends[b] << ": " << r.err;
    for (int k = 20; k <= 22; ++k) {
      by_backend[b].push_back(read_png_file(
          (out / std::string("f_").append(std::to_string(k)).append(".png")).string()));
    }
  }
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(by_backend[0][i].width, by_backend[1][i].width);
    ASSERT_EQ(by_backend[0][i].height, by_backend[1][i].height);
    EXPECT_EQ(differing_pixels(by_backend[0][i], by_backend[1][i]), 0u) << "frame " << 20 + i;
  }
}

TEST_F(RenderCommand, Mp4RenderIsDeterministic) {
  std::vector<Image> decoded[2];
  for (int pass = 0; pass < 2; ++pass) {
    const fs::path clip =
        dir_ / "out" / std::string("clip_").append(std::to_string(pass)).append(".mp4");
    const Outcome r =
        run({figure12a(), "-o", clip.string(), "--frames", "0:9", "--size", "320x180"});
    ASSERT_EQ(r.code, 0) << r.err;
    decoded[pass] = probe_video(clip.string(), true).decoded_rgba;
  }
  ASSERT_EQ(decoded[0].size(), 10u);
  ASSERT_EQ(decoded[1].size(), 10u);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(decoded[0][i].rgba, decoded[1][i].rgba) << "frame " << i;
  }
  EXPECT_GT(differing_pixels(decoded[0].front(), decoded[0].back()), 0u);  // not a still
}

TEST_F(RenderCommand, ExistingMp4IsKeptWithoutYAndReplacedWithIt) {
  const fs::path clip = dir_ / "out" / "clip.mp4";
  write_text(clip, "precious");
  const std::vector<std::string> args = {figure12a(), "-o",     clip.string(), "--frames",
                                         "0:4",       "--size", "320x180"};
  const Outcome refused = run(args);
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find("-y"), std::string::npos) << refused.err;
  EXPECT_EQ(read_text(clip), "precious");
  EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"clip.mp4"});

  std::vector<std::string> with_y = args;
  with_y.push_back("-y");
  const Outcome replaced = run(with_y);
  ASSERT_EQ(replaced.code, 0) << replaced.err;
  const VideoProbe probe = probe_video(clip.string());
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.frames, 5u);
}

TEST_F(RenderCommand, ExistingFirstPngIsKeptWithoutYAndReplacedWithIt) {
  const fs::path out = dir_ / "out";
  write_text(out / "f_0003.png", "precious");
  const std::vector<std::string> args = {
      figure12a(), "-o", (out / "f_%04d.png").string(), "--frames", "3:4", "--size", "320x180"};
  const Outcome refused = run(args);
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find("-y"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("f_0003.png"), std::string::npos) << refused.err;
  EXPECT_EQ(read_text(out / "f_0003.png"), "precious");
  EXPECT_EQ(listing(out), std::vector<std::string>{"f_0003.png"});  // f_0004 not written either

  std::vector<std::string> with_y = args;
  with_y.push_back("-y");
  const Outcome replaced = run(with_y);
  ASSERT_EQ(replaced.code, 0) << replaced.err;
  EXPECT_EQ(listing(out), (std::vector<std::string>{"f_0003.png", "f_0004.png"}));
  const Image image = read_png_file((out / "f_0003.png").string());
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 180);
}

// Any frame file of the sequence counts, not only the first.
TEST_F(RenderCommand, ExistingLaterPngIsKeptWithoutY) {
  const fs::path out = dir_ / "out";
  write_text(out / "f_4.png", "precious");
  const Outcome refused =
      run({figure12a(), "-o", (out / "f_%d.png").string(), "--frames", "3:4", "--size", "320x180"});
  EXPECT_EQ(refused.code, 2) << refused.err;
  EXPECT_NE(refused.err.find("f_4.png"), std::string::npos) << refused.err;
  EXPECT_EQ(read_text(out / "f_4.png"), "precious");
  EXPECT_EQ(listing(out), std::vector<std::string>{"f_4.png"});
}

// A strip is written last, but a missing folder fails before anything is rendered.
TEST_F(RenderCommand, StripIntoAMissingFolderFailsAtOnce) {
  const Outcome missing = run({figure12a(), "-o", (dir_ / "nowhere" / "strip.png").string(),
                               "--strip", "3", "--size", "320x180"});
  EXPECT_EQ(missing.code, 1) << missing.err;
  EXPECT_NE(missing.err.find("nowhere"), std::string::npos) << missing.err;
  EXPECT_EQ(missing.err.find("frames rendered"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir_ / "nowhere"));
}

// Each: exit 2, "error:" and the named problem on stderr, nothing in the output folder.
TEST_F(RenderCommand, BadUsageExits2AndWritesNothing) {
  const std::string out = (dir_ / "out").string();
  const std::string mp4 = out + "/clip.mp4";
  const std::string bad_scene =
      (source_dir() / "tests" / "scene" / "bad" / "34_density_negative.json").string();
  expect_usage_errors({
      {{figure12a(), "-o", out + "/clip.avi"}, "cannot tell the output format"},
      {{figure12a(), "-o", out + "/f.png", "--format", "png"}, "pattern"},
      {{figure12a(), "-o", mp4, "--frames", "10:5"}, "--frames 10:5"},
      {{figure12a(), "-o", mp4, "--frames", "0:151"}, "last frame is 150"},
      {{figure12a(), "-o", mp4, "--size", "321x180"}, "even"},
      {{figure12a(), "-o", mp4, "--size", "abc"}, "--size"},
      {{figure12a(), "-o", mp4, "--crf", "60"}, "--crf"},
      {{figure12a(), "-o", mp4, "--preset", "turbo"}, "turbo"},
      {{figure12a(), "-o", mp4, "--overlay", "bogus"}, "bogus"},
      {{figure12a(), "-o", mp4, "--aa", "bogus"}, "--aa"},
      {{figure12a(), "-o", mp4, "--backend", "bogus"}, "--backend"},
      {{bad_scene, "-o", mp4}, "/bodies/1/material/density"},
  });
}

TEST_F(RenderCommand, FullDeviceExits1NamingTheDeviceAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  const Outcome r = run(
      {figure12a(), "-o", "/dev/full", "--format", "mp4", "--frames", "0:9", "--size", "320x180"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
}

// An output folder that does not exist is an I/O failure (exit 1) that names the path.
TEST_F(RenderCommand, MissingOutputFolderExits1NamingThePath) {
  ASSERT_FALSE(fs::exists("/nonexistent_dir"));
  for (const std::string out : {"/nonexistent_dir/x.mp4", "/nonexistent_dir/f_%04d.png"}) {
    const Outcome r = run({figure12a(), "-o", out, "--frames", "0:1", "--size", "320x180"});
    EXPECT_EQ(r.code, 1) << out << "\n" << r.err;
    EXPECT_NE(r.err.find("/nonexistent_dir"), std::string::npos) << out << "\n" << r.err;
    EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << out << "\n" << r.err;
  }
}

class RenderInterrupt : public RenderCommand {
 protected:
  // Starts a 60 s render (1801 frames, a few seconds' work) of a fixed-camera scene to `clip` and
  // waits until the program reports at least `frames` rendered (its first line comes at a tenth,
  // 181 frames); the pid, or -1 after recording a failure.
  pid_t start_long_render(const fs::path& clip, std::size_t frames, fs::path& err_file) {
    const fs::path scene = fixed_camera_scene();
    if (scene.empty()) {
      ADD_FAILURE() << "figure12a.json has no \"camera\": \"auto\" to replace";
      return -1;
    }
    const pid_t pid = start({scene.string(), "-o", clip.string(), "--duration", "60", "--size",
                             "320x180", "--preset", "ultrafast"},
                            err_file);
    if (pid < 0) {
      ADD_FAILURE() << "cannot start " << program();
      return -1;
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (frames_reported(read_text(err_file)) < frames) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        ADD_FAILURE() << "the render ended before " << frames << " frames:\n"
                      << read_text(err_file);
        return -1;
      }
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(pid, SIGKILL);
        wait_for(pid);
        ADD_FAILURE() << "no progress line with " << frames << " frames in 120 s:\n"
                      << read_text(err_file);
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return pid;
  }
};

TEST_F(RenderInterrupt, SigintClosesTheMp4WithEveryFrameRendered) {
  const fs::path clip = dir_ / "out" / "clip.mp4";
  fs::path err_file;
  const pid_t pid = start_long_render(clip, 1, err_file);
  ASSERT_GE(pid, 0);
  ::kill(pid, SIGINT);
  const int code = wait_for(pid);
  const std::string err = read_text(err_file);
  EXPECT_EQ(code, 130) << err;
  const long n = frames_interrupted(err);
  ASSERT_GT(n, 0) << err;
  EXPECT_LT(n, 1801) << err;
  EXPECT_NE(err.find(std::string("written to ").append(clip.string())), std::string::npos) << err;
  const VideoProbe probe = probe_video(clip.string());
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.frames, static_cast<std::size_t>(n));
  EXPECT_NEAR(probe.duration_s, static_cast<double>(n) / 30.0, 1.0 / 30.0);
  EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"clip.mp4"});
}

// A GIF or WebM is written whole when the render stops: Ctrl-C leaves one with every frame
// rendered, and no temporary file.
TEST_F(RenderInterrupt, SigintFinishesTheGifAndWebmWithEveryFrameRendered) {
  for (const std::string kind : {"gif", "webm"}) {
    const fs::path clip = dir_ / "out" / ("clip." + kind);
    fs::path err_file;
    const pid_t pid = start_long_render(clip, 1, err_file);
    ASSERT_GE(pid, 0);
    ::kill(pid, SIGINT);
    const int code = wait_for(pid);
    const std::string err = read_text(err_file);
    EXPECT_EQ(code, 130) << err;
    const long n = frames_interrupted(err);
    ASSERT_GT(n, 0) << err;
    EXPECT_LT(n, 1801) << err;
    const VideoProbe probe = probe_video(clip.string());
    EXPECT_EQ(probe.codec, kind == "gif" ? "gif" : "vp9");
    EXPECT_EQ(probe.frames, static_cast<std::size_t>(n)) << kind;
    EXPECT_EQ(listing(dir_ / "out"), std::vector<std::string>{"clip." + kind});
    fs::remove(clip);
  }
}

// The MP4 is fragmented: a render killed outright leaves the fragments completed so far
// playable. The kill can land while a fragment is being written (a fragment takes several
// write calls), so the file may end inside its last sample: that cut tail is all that is lost.
TEST_F(RenderInterrupt, SigkillLeavesAPlayableMp4) {
  const fs::path clip = dir_ / "out" / "clip.mp4";
  fs::path err_file;
  const pid_t pid = start_long_render(clip, 60, err_file);
  ASSERT_GE(pid, 0);
  ::kill(pid, SIGKILL);
  EXPECT_EQ(wait_for(pid), 128 + SIGKILL);
  VideoProbe probe;
  ASSERT_NO_THROW(probe = probe_video(clip.string(), false, FileEnd::may_be_cut))
      << read_text(err_file);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_GE(probe.frames, 1u);
  EXPECT_LT(probe.frames, 1801u);
  RecordProperty("frames_kept", static_cast<int>(probe.frames));
}

// Frame 30 (1 s): the rocks move and touch the floor, so contacts and velocities have
// something to show.
TEST_F(RenderCommand, OverlaysDrawSomethingAndNoneDrawsNothing) {
  const fs::path plain_scene = fixed_camera_scene();
  const fs::path all_scene = fixed_camera_scene(R"(["rugosity", "contacts", "velocity"])");
  ASSERT_FALSE(plain_scene.empty());
  const Image plain = frame(plain_scene.string(), 30, {});
  const Image contacts_velocity =
      frame(plain_scene.string(), 30, {"--overlay", "contacts,velocity"});
  const Image rugosity = frame(plain_scene.string(), 30, {"--overlay", "rugosity"});
  const Image all_by_option =
      frame(plain_scene.string(), 30, {"--overlay", "rugosity,contacts,velocity"});
  const Image all_by_scene = frame(all_scene.string(), 30, {});
  const Image none = frame(all_scene.string(), 30, {"--overlay", "none"});
  ASSERT_EQ(plain.width, 320);
  EXPECT_GT(differing_pixels(plain, contacts_velocity), 0u);
  EXPECT_GT(differing_pixels(plain, rugosity), 0u);
  EXPECT_GT(differing_pixels(contacts_velocity, rugosity), 0u);
  // The scene's render.overlays and --overlay mean the same; "none" replaces the scene's list.
  EXPECT_GT(differing_pixels(plain, all_by_scene), 0u);
  EXPECT_EQ(differing_pixels(all_by_option, all_by_scene), 0u);
  EXPECT_EQ(none.width, 320);
  EXPECT_EQ(differing_pixels(plain, none), 0u);
  RecordProperty("contacts_velocity_pixels",
                 static_cast<int>(differing_pixels(plain, contacts_velocity)));
  RecordProperty("rugosity_pixels", static_cast<int>(differing_pixels(plain, rugosity)));
}

// The anti-aliasing modes differ only along edges: under a tenth of the frame.
TEST_F(RenderCommand, AntiAliasingModesDifferOnlyNearEdges) {
  const std::string scene = figure12a();
  const Image shader = frame(scene, 30, {"--aa", "shader"});
  const Image msaa = frame(scene, 30, {"--aa", "msaa"});
  const Image none = frame(scene, 30, {"--aa", "none"});
  ASSERT_EQ(shader.width, 320);
  ASSERT_EQ(msaa.width, 320);
  ASSERT_EQ(none.width, 320);
  const std::size_t limit = 320 * 180 / 10;
  for (const auto& [name, image] : {std::pair{"msaa", &msaa}, std::pair{"none", &none}}) {
    const std::size_t differ = differing_pixels(shader, *image);
    EXPECT_GT(differ, 0u) << name;
    EXPECT_LT(differ, limit) << name;
    RecordProperty(std::string(name).append("_pixels_differing"), static_cast<int>(differ));
  }
  EXPECT_GT(differing_pixels(msaa, none), 0u);
}

}  // namespace
