// `rugosim snapshot` through the program (README, "Snapshots"): goldens written with --update and
// what they record, the default tolerance rule against --exact, --threshold and --max-share, the
// actual and diff images and the summary a failure leaves (and a pass removes), --json for CI,
// --frames, --output, and the errors: a missing golden (exit 1, how to make it), a missing
// folder, an unreadable golden (exit 2).
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
#include <nlohmann/json.hpp>

#include "render/image.h"
#include "render/sinks/png_io.h"
#include "support/file_text.h"
#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rugosim::Image;
using rugosim::PngSettings;
using rugosim::read_png_file;
using rugosim::write_png_file;
using rugosim::testing::program;
using rugosim::testing::source_dir;

std::string figure12a() {
  return (source_dir() / "scenes" / "figure12a.json").string();
}

using rugosim::testing::read_text;

using rugosim::testing::write_text;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The names of the entries of a folder, sorted.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The names of a folder's entries that a failure leaves: *.actual.png, *.diff.png,
// *.summary.txt.
std::vector<std::string> failure_files(const fs::path& dir) {
  std::vector<std::string> found;
  for (const std::string& name : listing(dir)) {
    if (contains(name, ".actual.png") || contains(name, ".diff.png") ||
        contains(name, ".summary.txt")) {
      found.push_back(name);
    }
  }
  return found;
}

constexpr int kTimedOut = -2;

// The program's exit code, or 128 + the signal that ended it; kTimedOut after killing it when it
// runs longer than `limit`.
int wait_for(pid_t pid, std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return -1;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return kTimedOut;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

struct Outcome {
  int code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// A value a channel can be changed to so that it differs from `v` by exactly `by`.
std::uint8_t shifted(std::uint8_t v, int by) {
  return static_cast<std::uint8_t>(v >= 128 ? v - by : v + by);
}

// Changes the red channel of the pixels of [x0, x1] × [y0, y1] of a PNG file by exactly `by`.
void change_pixels(const fs::path& file, int x0, int y0, int x1, int y1, int by) {
  Image image = read_png_file(file.string());
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x)
      image.pixel(x, y)[0] = shifted(image.pixel(x, y)[0], by);
  }
  write_png_file(file.string(), image, PngSettings{});
}

bool is_red(const std::uint8_t* p) {
  return p[0] == 255 && p[1] == 0 && p[2] == 0;
}

// The washed-out actual frame: a light grey (luma blended 75 % towards white).
bool is_light_grey(const std::uint8_t* p) {
  return p[0] == p[1] && p[1] == p[2] && p[0] >= 191;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// Each test in its own folder, kept when the test fails (its path is printed) for a look at the
// goldens and what the program left, removed otherwise.
class SnapshotCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           std::string("rugosim_snapshot_").append(std::to_string(::getpid())) / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "golden");
    golden_ = dir_ / "golden";
  }
  void TearDown() override {
    if (HasFailure()) {
      std::fprintf(stderr, "outputs kept in %s\n", dir_.c_str());
    } else {
      fs::remove_all(dir_);
      std::error_code ignored;
      fs::remove(dir_.parent_path(), ignored);  // when this was the last test's folder
    }
  }

  // Runs `PREFIX... rugosim snapshot ARGS...` with stdout and stderr to files of the test's
  // folder, and returns what it wrote there; kills it after `limit`.
  Outcome run_with(const std::vector<std::string>& prefix, const std::vector<std::string>& args,
                   std::chrono::seconds limit = std::chrono::seconds(300)) {
    ++runs_;
    const fs::path out_file = dir_ / std::string("stdout_").append(std::to_string(runs_));
    const fs::path err_file = dir_ / std::string("stderr_").append(std::to_string(runs_));
    std::vector<std::string> all = prefix;
    all.push_back(program());
    all.push_back("snapshot");
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t pid = -1;
    const int rc = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    Outcome r;
    if (rc != 0) {
      r.err = std::string("cannot start ").append(argv[0]).append(": ").append(std::strerror(rc));
      return r;
    }
    r.code = wait_for(pid, limit);
    r.out = read_text(out_file);
    r.err = read_text(err_file);
    return r;
  }

  Outcome run(const std::vector<std::string>& args) { return run_with({}, args); }

  // `rugosim snapshot SCENE --golden <the test's golden folder> ARGS...`.
  Outcome snap(const std::string& scene, const std::vector<std::string>& args) {
    std::vector<std::string> all = {scene, "--golden", golden_.string()};
    all.insert(all.end(), args.begin(), args.end());
    return run(all);
  }

  // Writes goldens of `scene` with extra options; records a failure when the program fails.
  void update(const std::string& scene, const std::vector<std::string>& args) {
    std::vector<std::string> all = {"--update"};
    all.insert(all.end(), args.begin(), args.end());
    const Outcome r = snap(scene, all);
    ASSERT_EQ(r.code, 0) << r.err;
  }

  fs::path golden(std::size_t frame, const std::string& kind = "") const {
    return golden_ / std::string("figure12a_")
                         .append(std::to_string(frame))
                         .append(kind.empty() ? "" : ".")
                         .append(kind)
                         .append(".png");
  }

  fs::path dir_;
  fs::path golden_;
  int runs_ = 0;
};

// figure12a is 5 s at 30 fps: frames 0..150, four of them spread over the clip by default.
TEST_F(SnapshotCommand, UpdateThenRerunPasses) {
  const Outcome written = snap(figure12a(), {"--update", "--size", "160x90"});
  ASSERT_EQ(written.code, 0) << written.err;
  EXPECT_TRUE(contains(written.err, "wrote 4 golden frames")) << written.err;
  EXPECT_EQ(listing(golden_),
            (std::vector<std::string>{"figure12a.json", "figure12a_0.png", "figure12a_100.png",
                                      "figure12a_150.png", "figure12a_50.png"}));
  for (const std::size_t k : {0u, 50u, 100u, 150u}) {
    const Image image = read_png_file(golden(k).string());
    EXPECT_EQ(image.width, 160) << k;
    EXPECT_EQ(image.height, 90) << k;
  }

  const json metadata = json::parse(read_text(golden_ / "figure12a.json"));
  std::vector<std::string> keys;
  for (const auto& [key, value] : metadata.items())
    keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"anti_aliasing", "frames", "renderer", "rugosim",
                                            "scene", "size"}));
  EXPECT_EQ(metadata.at("scene"), "figure12a");
  EXPECT_EQ(metadata.at("frames"), json::parse("[0, 50, 100, 150]"));
  EXPECT_EQ(metadata.at("size"), json::parse("[160, 90]"));
  EXPECT_EQ(metadata.at("anti_aliasing"), "shader");
  ASSERT_TRUE(metadata.at("renderer").is_string());
  EXPECT_TRUE(contains(metadata.at("renderer").get<std::string>(), "llvmpipe"))
      << metadata.at("renderer");
  ASSERT_TRUE(metadata.at("rugosim").is_string());
  EXPECT_FALSE(metadata.at("rugosim").get<std::string>().empty());

  // The rerun takes frames and size from the goldens.
  const Outcome rerun = snap(figure12a(), {});
  EXPECT_EQ(rerun.code, 0) << rerun.err;
  EXPECT_TRUE(contains(rerun.err, "identical")) << rerun.err;
  EXPECT_TRUE(contains(rerun.err, "frame 150: identical")) << rerun.err;
  EXPECT_TRUE(contains(rerun.err, "figure12a: passed (4 frames)")) << rerun.err;
  EXPECT_EQ(rerun.out, "");  // no JSON unless asked
  EXPECT_TRUE(failure_files(golden_).empty());
  EXPECT_EQ(listing(golden_).size(), 5u);
}

// A transparent background: the goldens keep alpha (RGBA), a rerun is identical, and a golden
// whose background was made opaque fails (alpha is compared like the colours).
TEST_F(SnapshotCommand, TransparentGoldensKeepAlphaAndItIsCompared) {
  std::string text = read_text(figure12a());
  const std::string from = R"("overlays": [])";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), R"("overlays": [], "background": "transparent")");
  const fs::path scene = dir_ / "figure12a.json";
  write_text(scene, text);
  update(scene.string(), {"--size", "160x90", "--frames", "150"});
  Image image = read_png_file(golden(150).string());
  EXPECT_EQ(image.rgba[3], 0) << "the corner is background";
  EXPECT_TRUE(contains(snap(scene.string(), {}).err, "frame 150: identical"));
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
    image.rgba[i] = 255;
  write_png_file(golden(150).string(), image, PngSettings{});
  const Outcome r = snap(scene.string(), {});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "frame 150: failed")) << r.err;
}

// One channel of one pixel off by 100: 1 of 14 400 pixels (0.007 %) fails the threshold, within
// the default share of 0.1 %; --exact fails it and draws it.
TEST_F(SnapshotCommand, OnePixelChangePassesTheDefaultRuleAndFailsExact) {
  update(figure12a(), {"--size", "160x90"});
  const Image original = read_png_file(golden(50).string());
  const int x = 80, y = 45;
  change_pixels(golden(50), x, y, x, y, 100);

  const Outcome loose = snap(figure12a(), {});
  EXPECT_EQ(loose.code, 0) << loose.err;
  EXPECT_TRUE(contains(loose.err, "frame 50: passed")) << loose.err;
  EXPECT_TRUE(contains(loose.err, "figure12a: passed")) << loose.err;
  EXPECT_TRUE(failure_files(golden_).empty());

  const Outcome exact = snap(figure12a(), {"--exact"});
  EXPECT_EQ(exact.code, 1) << exact.err;
  EXPECT_TRUE(contains(exact.err, "frame 50: failed")) << exact.err;
  EXPECT_TRUE(contains(exact.err, "frame 0: identical")) << exact.err;
  EXPECT_EQ(failure_files(golden_),
            (std::vector<std::string>{"figure12a.summary.txt", "figure12a_50.actual.png",
                                      "figure12a_50.diff.png"}));
  // The actual frame is what was rendered: the golden as it was before the change.
  const Image actual = read_png_file(golden(50, "actual").string());
  ASSERT_EQ(actual.width, 160);
  ASSERT_EQ(actual.height, 90);
  EXPECT_TRUE(actual.rgba == original.rgba);

  // Red: the pixel, and the 1 px rectangle 3 px outside it; the rest washed-out grey.
  const Image diff = read_png_file(golden(50, "diff").string());
  ASSERT_EQ(diff.width, 160);
  ASSERT_EQ(diff.height, 90);
  EXPECT_TRUE(is_red(diff.pixel(x, y)));
  std::string wrong;
  for (int py = 0; py < diff.height; ++py) {
    for (int px = 0; px < diff.width; ++px) {
      const bool on_rectangle = (std::abs(px - x) == 3 && std::abs(py - y) <= 3) ||
                                (std::abs(py - y) == 3 && std::abs(px - x) <= 3);
      const bool red_expected = (px == x && py == y) || on_rectangle;
      const std::uint8_t* p = diff.pixel(px, py);
      if (red_expected ? !is_red(p) : !is_light_grey(p)) {
        wrong.append(" (").append(std::to_string(px)).append(", ").append(std::to_string(py));
        wrong.append(")");
      }
    }
  }
  EXPECT_EQ(wrong, "") << "diff pixels neither red where expected nor light grey elsewhere";

  const std::string summary = read_text(golden_ / "figure12a.summary.txt");
  EXPECT_TRUE(contains(summary, "frame 50: failed")) << summary;
  EXPECT_TRUE(contains(summary, "(80, 45)")) << summary;
  EXPECT_FALSE(contains(summary, "frame 0: failed")) << summary;

  // A pass removes what the failure left.
  const Outcome again = snap(figure12a(), {});
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_TRUE(failure_files(golden_).empty());
}

// figure12a with an explicit camera (so the scale is known and does not follow the bodies),
// rock_0 moved right by `dx` metres.
std::string fixed_camera_scene(double dx) {
  json scene = json::parse(read_text(figure12a()), nullptr, true, /*ignore_comments=*/true);
  scene["render"]["camera"] = json::parse(R"({"center": [0, 1.1], "height": 2.6})");
  for (json& body : scene.at("bodies")) {
    if (body.at("name") == "rock_0") body["position"][0] = body["position"][0].get<double>() + dx;
  }
  return scene.dump(2);
}

TEST_F(SnapshotCommand, MovingABodyFailsAndTheDiffMarksIt) {
  const int width = 256, height = 144;
  const double pixel = 2.6 / height;  // m per pixel
  const int shift = 6;                // px
  const fs::path scene = dir_ / "rocks.json";
  write_text(scene, fixed_camera_scene(0.0));
  const std::vector<std::string> options = {"--frames", "0", "--size", "256x144"};
  update(scene.string(), options);
  write_text(scene, fixed_camera_scene(shift * pixel));

  std::vector<std::string> with_json = options;
  with_json.push_back("--json");
  const Outcome r = snap(scene.string(), with_json);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "frame 0: failed")) << r.err;

  // rock_0 (radius 0.22 m, irregular: at most about 0.32 m from its centre) at (-1.2, 0.9), in
  // pixels from the top left; the change lies within `reach` of the middle of its two places.
  const double mid_x = width / 2.0 + -1.2 / pixel + shift / 2.0;
  const double mid_y = height / 2.0 - (0.9 - 1.1) / pixel;
  const double reach = 0.35 / pixel + shift / 2.0 + 2.0;
  auto distance = [&](int x, int y) {
    return std::max(std::abs(x + 0.5 - mid_x), std::abs(y + 0.5 - mid_y));
  };

  json report;
  ASSERT_NO_THROW(report = json::parse(r.out)) << r.out;
  EXPECT_EQ(report.at("passed"), false);
  ASSERT_EQ(report.at("frames").size(), 1u);
  const json& frame = report.at("frames").at(0);
  EXPECT_EQ(frame.at("frame"), 0);
  EXPECT_EQ(frame.at("status"), "failed");
  EXPECT_GT(frame.at("failing_share").get<double>(), 0.001);
  ASSERT_TRUE(frame.contains("box")) << frame.dump();
  const auto box = frame.at("box").get<std::vector<int>>();
  ASSERT_EQ(box.size(), 4u);
  EXPECT_LE(distance(box[0], box[1]), reach) << frame.dump();
  EXPECT_LE(distance(box[2], box[3]), reach) << frame.dump();
  EXPECT_GE(box[2] - box[0] + 1, shift) << frame.dump();
  // Centred on the body (its outline is irregular: a few pixels either way).
  EXPECT_NEAR((box[0] + box[2] + 1) / 2.0, mid_x, 4.0) << frame.dump();
  EXPECT_NEAR((box[1] + box[3] + 1) / 2.0, mid_y, 4.0) << frame.dump();
  // The body's old and new places both show: the box reaches either side of the middle.
  EXPECT_LT(box[0], mid_x - shift) << frame.dump();
  EXPECT_GT(box[2], mid_x + shift) << frame.dump();

  const Image diff = read_png_file((golden_ / "rocks_0.diff.png").string());
  ASSERT_EQ(diff.width, width);
  ASSERT_EQ(diff.height, height);
  std::size_t red_near = 0, red_far = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!is_red(diff.pixel(x, y))) continue;
      // The rectangle's lines lie 3 px outside the box of the failing pixels.
      if (distance(x, y) <= reach + 4.0) {
        ++red_near;
      } else {
        ++red_far;
      }
    }
  }
  EXPECT_GT(red_near, 100u);
  EXPECT_EQ(red_far, 0u);
  RecordProperty("failing_pixels", frame.at("failing_pixels").get<int>());
}

TEST_F(SnapshotCommand, MissingGoldenSaysHowToCreateIt) {
  // An empty golden folder: every frame is missing; the actual frames are left for a look.
  const Outcome empty = snap(figure12a(), {"--size", "160x90", "--frames", "0,50", "--json"});
  EXPECT_EQ(empty.code, 1) << empty.err;
  EXPECT_TRUE(contains(empty.err, "--update")) << empty.err;
  EXPECT_TRUE(contains(empty.err, std::string("no golden ").append(golden(0).string())))
      << empty.err;
  json report;
  ASSERT_NO_THROW(report = json::parse(empty.out)) << empty.out;
  EXPECT_EQ(report.at("passed"), false);
  ASSERT_EQ(report.at("frames").size(), 2u);
  for (const json& frame : report.at("frames")) {
    EXPECT_EQ(frame.at("status"), "missing");
    EXPECT_FALSE(frame.contains("diff"));
    ASSERT_TRUE(frame.contains("actual"));
    EXPECT_TRUE(fs::exists(frame.at("actual").get<std::string>())) << frame.dump();
  }
  EXPECT_TRUE(fs::exists(golden(0, "actual")));
  EXPECT_TRUE(fs::exists(golden(50, "actual")));

  // One frame's golden deleted.
  update(figure12a(), {"--size", "160x90"});
  EXPECT_TRUE(failure_files(golden_).empty());
  fs::remove(golden(100));
  const Outcome one = snap(figure12a(), {});
  EXPECT_EQ(one.code, 1) << one.err;
  EXPECT_TRUE(contains(one.err, "frame 100: no golden")) << one.err;
  EXPECT_TRUE(contains(one.err, "--update")) << one.err;
  EXPECT_TRUE(contains(one.err, "frame 50: identical")) << one.err;
  EXPECT_TRUE(fs::exists(golden(100, "actual")));
  EXPECT_TRUE(fs::exists(golden_ / "figure12a.summary.txt"));

  // No golden folder at all: a usage error, with the command that makes it; nothing created.
  const fs::path nowhere = dir_ / "nowhere";
  const Outcome missing = run({figure12a(), "--golden", nowhere.string(), "--size", "160x90"});
  EXPECT_EQ(missing.code, 2) << missing.err;
  EXPECT_TRUE(contains(missing.err, "--update")) << missing.err;
  EXPECT_TRUE(contains(missing.err, nowhere.string())) << missing.err;
  EXPECT_FALSE(fs::exists(nowhere));
}

TEST_F(SnapshotCommand, CorruptGoldenIsAClearError) {
  update(figure12a(), {"--size", "160x90", "--frames", "0,30"});
  const std::string valid = read_text(golden(30));
  ASSERT_GT(valid.size(), 100u);
  struct Case {
    std::string what;
    std::string bytes;
  };
  const std::vector<Case> cases = {
      {"garbage", "this is not a PNG file, only some text of about the same size"},
      {"truncated", valid.substr(0, valid.size() / 2)},
      {"empty", ""},
  };
  for (const Case& c : cases) {
    write_text(golden(30), c.bytes);
    const Outcome r = snap(figure12a(), {});
    EXPECT_EQ(r.code, 2) << c.what << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, golden(30).string())) << c.what << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "cannot be read")) << c.what << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "--update")) << c.what << "\n" << r.err;
  }
  // The goldens' description unreadable: a usage error naming it.
  write_text(golden(30), valid);
  write_text(golden_ / "figure12a.json", "{\"frames\": [0, 30");
  const Outcome bad_json = snap(figure12a(), {});
  EXPECT_EQ(bad_json.code, 2) << bad_json.err;
  EXPECT_TRUE(contains(bad_json.err, (golden_ / "figure12a.json").string())) << bad_json.err;
}

// Frames 0, 50, 100, 150: identical, passed (1 pixel off by 100), failed (10 × 10 pixels off by
// 100), missing.
TEST_F(SnapshotCommand, JsonOutputParses) {
  update(figure12a(), {"--size", "160x90"});
  change_pixels(golden(50), 70, 40, 70, 40, 100);
  change_pixels(golden(100), 20, 30, 29, 39, 100);
  fs::remove(golden(150));
  const Outcome r = snap(figure12a(), {"--json"});
  EXPECT_EQ(r.code, 1) << r.err;
  json report;
  ASSERT_NO_THROW(report = json::parse(r.out)) << r.out;

  EXPECT_EQ(report.at("scene"), "figure12a");
  EXPECT_EQ(report.at("passed"), false);
  EXPECT_EQ(report.at("rule"), json::parse(R"({"exact": false, "threshold": 16,
                                                "max_share": 0.001})"));
  const json& renderer = report.at("renderer");
  ASSERT_TRUE(renderer.at("golden").is_string());
  EXPECT_TRUE(contains(renderer.at("golden").get<std::string>(), "llvmpipe")) << renderer;
  EXPECT_EQ(renderer.at("current"), renderer.at("golden"));

  const json& frames = report.at("frames");
  ASSERT_EQ(frames.size(), 4u);
  std::vector<std::string> statuses;
  for (const json& f : frames)
    statuses.push_back(f.at("status").get<std::string>());
  EXPECT_EQ(statuses, (std::vector<std::string>{"identical", "passed", "failed", "missing"}));
  const double pixels = 160.0 * 90.0;
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(frames[i].at("frame"), 50 * i);
    EXPECT_EQ(frames[i].at("golden"), golden(50 * i).string());
  }

  const json& identical = frames[0];
  EXPECT_EQ(identical.value("differing_pixels", -1), 0);
  EXPECT_EQ(identical.value("failing_pixels", -1), 0);
  EXPECT_FALSE(identical.contains("worst_at"));
  EXPECT_FALSE(identical.contains("box"));
  EXPECT_FALSE(identical.contains("actual"));
  EXPECT_FALSE(identical.contains("diff"));

  const json& passed = frames[1];
  EXPECT_EQ(passed.at("differing_pixels"), 1);
  EXPECT_EQ(passed.at("failing_pixels"), 1);
  EXPECT_DOUBLE_EQ(passed.at("failing_share").get<double>(), 1.0 / pixels);
  EXPECT_EQ(passed.at("worst"), 100);
  EXPECT_EQ(passed.at("worst_at"), json::parse("[70, 40]"));
  EXPECT_EQ(passed.at("box"), json::parse("[70, 40, 70, 40]"));
  EXPECT_FALSE(passed.contains("actual"));
  EXPECT_FALSE(passed.contains("diff"));

  const json& failed = frames[2];
  EXPECT_EQ(failed.at("differing_pixels"), 100);
  EXPECT_EQ(failed.at("failing_pixels"), 100);
  EXPECT_DOUBLE_EQ(failed.at("failing_share").get<double>(), 100.0 / pixels);
  EXPECT_EQ(failed.at("worst"), 100);
  EXPECT_EQ(failed.at("worst_at"), json::parse("[20, 30]"));
  EXPECT_EQ(failed.at("box"), json::parse("[20, 30, 29, 39]"));
  EXPECT_EQ(failed.at("actual"), golden(100, "actual").string());
  EXPECT_EQ(failed.at("diff"), golden(100, "diff").string());
  EXPECT_TRUE(fs::exists(golden(100, "actual")));
  EXPECT_TRUE(fs::exists(golden(100, "diff")));

  const json& missing = frames[3];
  EXPECT_EQ(missing.at("actual"), golden(150, "actual").string());
  EXPECT_TRUE(fs::exists(golden(150, "actual")));
  EXPECT_FALSE(missing.contains("diff"));

  // Passing: "passed": true, and stdout is still one JSON object.
  update(figure12a(), {"--size", "160x90"});
  const Outcome ok = snap(figure12a(), {"--json"});
  EXPECT_EQ(ok.code, 0) << ok.err;
  json passing;
  ASSERT_NO_THROW(passing = json::parse(ok.out)) << ok.out;
  EXPECT_EQ(passing.at("passed"), true);
  for (const json& f : passing.at("frames"))
    EXPECT_EQ(f.at("status"), "identical");
}

TEST_F(SnapshotCommand, FramesOption) {
  update(figure12a(), {"--size", "160x90", "--frames", "0,10:20:10"});
  EXPECT_EQ(listing(golden_), (std::vector<std::string>{"figure12a.json", "figure12a_0.png",
                                                        "figure12a_10.png", "figure12a_20.png"}));
  const json metadata = json::parse(read_text(golden_ / "figure12a.json"));
  EXPECT_EQ(metadata.at("frames"), json::parse("[0, 10, 20]"));

  // Without --frames: the goldens' frames.
  const Outcome rerun = snap(figure12a(), {"--json"});
  EXPECT_EQ(rerun.code, 0) << rerun.err;
  EXPECT_TRUE(contains(rerun.err, "(3 frames)")) << rerun.err;
  json report;
  ASSERT_NO_THROW(report = json::parse(rerun.out)) << rerun.out;
  std::vector<std::size_t> frames;
  for (const json& f : report.at("frames"))
    frames.push_back(f.at("frame").get<std::size_t>());
  EXPECT_EQ(frames, (std::vector<std::size_t>{0, 10, 20}));

  // A subset, in any order and with repeats.
  const Outcome subset = snap(figure12a(), {"--frames", "20,0,20"});
  EXPECT_EQ(subset.code, 0) << subset.err;
  EXPECT_TRUE(contains(subset.err, "(2 frames)")) << subset.err;

  // Bad lists: exit 2 naming --frames, nothing written. The clip's last frame is 150.
  for (const std::string list :
       {"x", "5:1", "151", "0:200:50", "0:10:0", "1:2:3:4", "-1", "3,,4", "0:1x", " 1"}) {
    const Outcome bad = snap(figure12a(), {"--frames", list});
    EXPECT_EQ(bad.code, 2) << list << "\n" << bad.err;
    EXPECT_TRUE(contains(bad.err, "--frames")) << list << "\n" << bad.err;
    EXPECT_TRUE(failure_files(golden_).empty()) << list;
  }
  const Outcome past = snap(figure12a(), {"--frames", "0,151"});
  EXPECT_TRUE(contains(past.err, "last frame, 150")) << past.err;
}

// A range far past the clip is refused like any frame past it, at once: the list is not
// expanded into billions of frame numbers first. Run under a 1 GiB address-space limit so that
// a program that does expand it fails (std::bad_alloc, exit 1) instead of taking the machine's
// memory; ASan needs more address space than that, so it is left out there.
TEST_F(SnapshotCommand, HugeFrameRangeIsRefusedAtOnce) {
  if (kAddressSanitizer) GTEST_SKIP() << "ulimit -v and AddressSanitizer do not mix";
  update(figure12a(), {"--size", "160x90", "--frames", "0"});
  const std::vector<std::string> limited = {"/bin/sh", "-c", "ulimit -v 1048576 && exec \"$@\"",
                                            "sh"};
  // 4e9 frames; and the largest frame number, after which `k += step` wraps to 0.
  for (const std::string list : {"0:4000000000", "18446744073709551615"}) {
    const Outcome r =
        run_with(limited, {figure12a(), "--golden", golden_.string(), "--frames", list});
    EXPECT_EQ(r.code, 2) << list << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, "past the clip's last frame, 150")) << list << "\n" << r.err;
  }
}

// The goldens' description (name.json) is checked as the options are: a frame or a size of the
// wrong type is an error naming the file (exit 2, as for an unreadable golden), found before
// anything is rendered. A negative frame number would otherwise become 2^64 - 1 and the program
// would simulate towards it without end (it is killed after 10 s here).
TEST_F(SnapshotCommand, BadGoldenDescriptionIsAUsageError) {
  update(figure12a(), {"--size", "160x90", "--frames", "0"});
  const fs::path description = golden_ / "figure12a.json";
  json metadata = json::parse(read_text(description));
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"size", R"("big")"}, {"frames", "[-1]"}, {"frames", R"("0")"}}) {
    json changed = metadata;
    changed[key] = json::parse(value);
    write_text(description, changed.dump());
    const Outcome r =
        run_with({}, {figure12a(), "--golden", golden_.string()}, std::chrono::seconds(10));
    const std::string shown = std::string("\"").append(key).append("\": ").append(value);
    EXPECT_EQ(r.code, 2) << shown << (r.code == kTimedOut ? " (killed after 10 s)" : "") << "\n"
                         << r.err;
    EXPECT_TRUE(contains(r.err, description.string())) << shown << "\n" << r.err;
  }
}

// 1 pixel off by 20: within --threshold 32 even with --max-share 0; past --threshold 10 with
// --max-share 0, but within the default share.
TEST_F(SnapshotCommand, ThresholdAndShareOptions) {
  update(figure12a(), {"--size", "160x90", "--frames", "30"});
  change_pixels(golden(30), 100, 60, 100, 60, 20);

  const Outcome within = snap(figure12a(), {"--threshold", "32", "--max-share", "0", "--json"});
  EXPECT_EQ(within.code, 0) << within.err;
  EXPECT_TRUE(contains(within.err, "frame 30: passed")) << within.err;
  EXPECT_TRUE(failure_files(golden_).empty());
  json report;
  ASSERT_NO_THROW(report = json::parse(within.out)) << within.out;
  EXPECT_EQ(report.at("rule"), json::parse(R"({"exact": false, "threshold": 32,
                                                "max_share": 0.0})"));
  EXPECT_EQ(report.at("frames").at(0).at("differing_pixels"), 1);
  EXPECT_EQ(report.at("frames").at(0).at("failing_pixels"), 0);
  EXPECT_EQ(report.at("frames").at(0).at("worst"), 20);

  const Outcome past = snap(figure12a(), {"--threshold", "10", "--max-share", "0"});
  EXPECT_EQ(past.code, 1) << past.err;
  EXPECT_TRUE(contains(past.err, "frame 30: failed")) << past.err;
  EXPECT_TRUE(fs::exists(golden(30, "diff")));
  const Image diff = read_png_file(golden(30, "diff").string());
  EXPECT_TRUE(is_red(diff.pixel(100, 60)));

  const Outcome shared = snap(figure12a(), {"--threshold", "10"});
  EXPECT_EQ(shared.code, 0) << shared.err;
  EXPECT_TRUE(failure_files(golden_).empty());

  // Within the threshold but not exact: orange in the diff of an otherwise failing frame.
  change_pixels(golden(30), 10, 10, 10, 10, 100);
  const Outcome mixed = snap(figure12a(), {"--threshold", "32", "--max-share", "0"});
  EXPECT_EQ(mixed.code, 1) << mixed.err;
  const Image mixed_diff = read_png_file(golden(30, "diff").string());
  const std::uint8_t* orange = mixed_diff.pixel(100, 60);
  EXPECT_TRUE(orange[0] == 0xff && orange[1] == 0xa5 && orange[2] == 0x00)
      << int{orange[0]} << " " << int{orange[1]} << " " << int{orange[2]};
  EXPECT_TRUE(is_red(mixed_diff.pixel(10, 10)));

  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"--threshold", "256"},
                                             {"--threshold", "-1"},
                                             {"--max-share", "1.5"},
                                             {"--max-share", "-0.1"},
                                             {"--max-share", "nan"}}) {
    const Outcome r = snap(figure12a(), bad);
    EXPECT_EQ(r.code, 2) << bad[0] << " " << bad[1] << "\n" << r.err;
  }
}

// --output DIR takes a failure's images and summary instead of the golden folder; a pass
// clears it.
TEST_F(SnapshotCommand, OutputFolderTakesTheFailureFiles) {
  update(figure12a(), {"--size", "160x90", "--frames", "0,60"});
  const std::string original = read_text(golden(60));
  change_pixels(golden(60), 0, 0, 159, 89, 100);
  const fs::path elsewhere = dir_ / "artifacts" / "snapshots";
  const Outcome failed = snap(figure12a(), {"--output", elsewhere.string()});
  EXPECT_EQ(failed.code, 1) << failed.err;
  EXPECT_TRUE(contains(failed.err, elsewhere.string())) << failed.err;
  EXPECT_TRUE(failure_files(golden_).empty());
  ASSERT_TRUE(fs::is_directory(elsewhere));
  EXPECT_EQ(listing(elsewhere),
            (std::vector<std::string>{"figure12a.summary.txt", "figure12a_60.actual.png",
                                      "figure12a_60.diff.png"}));

  write_text(golden(60), original);
  const Outcome passed = snap(figure12a(), {"--output", elsewhere.string()});
  EXPECT_EQ(passed.code, 0) << passed.err;
  EXPECT_TRUE(listing(elsewhere).empty());
}

}  // namespace
