// What the tests of `rugosim render` share (tests/app): running the program with its stderr
// kept, a folder of each test's own, and the pixels of one rendered frame.
#pragma once

#include <algorithm>
#include <cerrno>
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
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/sinks/png_io.h"
#include "support/file_text.h"
#include "support/program_under_test.h"

namespace rugosim::testing {

namespace fs = std::filesystem;

inline std::string figure12a() {
  return (source_dir() / "scenes" / "figure12a.json").string();
}

// How far one image is from another of the same size, over its first `channels` channels
// (3: colour only; 4: with alpha).
struct ImageDifference {
  double mean = 0.0;       // mean |difference| over those channels of every pixel, in levels
  double far_share = 0.0;  // share of pixels with one of them more than `far` levels off
};
inline ImageDifference image_difference(const Image& a, const Image& b, std::size_t channels,
                                        int far) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) {
    return {255.0, 1.0};
  }
  std::size_t far_pixels = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < channels; ++c) {
      const int d = std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]});
      sum += d;
      worst = std::max(worst, d);
    }
    far_pixels += worst > far ? 1u : 0u;
  }
  const double pixels = static_cast<double>(a.rgba.size() / 4);
  return {sum / (static_cast<double>(channels) * pixels), static_cast<double>(far_pixels) / pixels};
}

// Pixels that differ in any channel; all of them when the sizes differ.
inline std::size_t differing_pixels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) {
    return std::max(a.rgba.size(), b.rgba.size()) / 4 + 1;
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
    if (!std::equal(a.rgba.begin() + static_cast<std::ptrdiff_t>(i),
                    a.rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                    b.rgba.begin() + static_cast<std::ptrdiff_t>(i))) {
      ++count;
    }
  }
  return count;
}

// The names of the entries of a folder, sorted.
inline std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The largest N of the "progress: N/M frames rendered" lines of a stderr file.
inline std::size_t frames_reported(const std::string& err) {
  std::size_t most = 0;
  std::istringstream lines(err);
  const std::string prefix = "progress: ";
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(prefix, 0) != 0 || line.find("frames rendered") == std::string::npos) continue;
    most = std::max<std::size_t>(most, std::strtoul(line.c_str() + prefix.size(), nullptr, 10));
  }
  return most;
}

// N of the summary line "interrupted: N frames written to ..."; -1 when there is none.
inline long frames_interrupted(const std::string& err) {
  const std::string key = "interrupted: ";
  const std::size_t at = err.find(key);
  if (at == std::string::npos) return -1;
  return std::strtol(err.c_str() + at + key.size(), nullptr, 10);
}

// The program's exit code, or 128 + the signal that ended it.
inline int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

struct Outcome {
  int code = -1;
  std::string err;  // what the program wrote on stderr
};

// Each test in its own folder, kept when the test fails (its path is printed) for a look at the
// outputs, removed otherwise.
class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           std::string("rugosim_render_").append(std::to_string(::getpid())) / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
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

  // Starts `rugosim render ARGS...` with stdout discarded and stderr to a new file of the test's
  // folder (returned in `err_file`); -1 when it cannot start.
  pid_t start(const std::vector<std::string>& args, fs::path& err_file) {
    err_file = dir_ / std::string("stderr_").append(std::to_string(++runs_)).append(".txt");
    std::vector<std::string> all = {program(), "render"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    // SIGINT as a terminal would deliver it, even when this test runs in the background.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    pid_t pid = -1;
    const int rc = ::posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    return rc == 0 ? pid : -1;
  }

  Outcome run(const std::vector<std::string>& args) {
    fs::path err_file;
    const pid_t pid = start(args, err_file);
    if (pid < 0) return {};
    Outcome r;
    r.code = wait_for(pid);
    r.err = read_text(err_file);
    return r;
  }

  // figure12a with a fixed camera (so rendering starts at the first frame, no simulation of the
  // whole clip before it) and the given render.overlays (a JSON list).
  fs::path fixed_camera_scene(const std::string& overlays = "[]") {
    std::string text = read_text(figure12a());
    const std::string from = R"("camera": "auto", "overlays": [])";
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return {};
    text.replace(at, from.size(),
                 std::string(R"("camera": {"center": [0, 1.1], "height": 2.6}, "overlays": )")
                     .append(overlays));
    const fs::path path =
        dir_ / std::string("fixed_camera_").append(std::to_string(++scenes_)).append(".json");
    write_text(path, text);
    return path;
  }

  // Renders one frame of `scene` to a PNG (size 320x180 unless `extra` has --size) with extra
  // options; empty on failure.
  Image frame(const std::string& scene, std::size_t index, const std::vector<std::string>& extra) {
    const fs::path out = dir_ / "out" / std::string("one_").append(std::to_string(++frames_));
    fs::create_directories(out);
    const std::string range = std::to_string(index).append(":").append(std::to_string(index));
    std::vector<std::string> args = {scene, "-o", (out / "f_%d.png").string(), "--frames", range};
    if (std::find(extra.begin(), extra.end(), "--size") == extra.end()) {
      args.insert(args.end(), {"--size", "320x180"});
    }
    args.insert(args.end(), extra.begin(), extra.end());
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    const fs::path file = out / std::string("f_").append(std::to_string(index)).append(".png");
    if (r.code != 0 || !fs::exists(file)) return {};
    return read_png_file(file.string());
  }

  // A bad command line and a part of what its error must say.
  struct UsageCase {
    std::vector<std::string> args;
    std::string message;
  };
  // Each case exits 2 with "error" and its message on stderr, leaving out/ empty (emptied after
  // each case).
  void expect_usage_errors(const std::vector<UsageCase>& cases) {
    for (const UsageCase& c : cases) {
      std::string shown;
      for (const std::string& a : c.args)
        shown.append(" ").append(a);
      const Outcome r = run(c.args);
      EXPECT_EQ(r.code, 2) << shown << "\n" << r.err;
      EXPECT_NE(r.err.find("error"), std::string::npos) << shown << "\n" << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos)
          << shown << "\nstderr lacks \"" << c.message << "\":\n"
          << r.err;
      EXPECT_TRUE(listing(dir_ / "out").empty()) << shown;
      fs::remove_all(dir_ / "out");
      fs::create_directories(dir_ / "out");
    }
  }

  fs::path dir_;
  int runs_ = 0;
  int scenes_ = 0;
  int frames_ = 0;
};

}  // namespace rugosim::testing
