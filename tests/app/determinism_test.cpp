// Determinism through the program (issue 7): the same scene, seed and build give the same bytes
// of telemetry and the same pixels whatever the thread counts: llvmpipe's rasteriser threads
// (--gl-threads, LP_NUM_THREADS), the PNG workers (--png-workers), the GL backend, and from one
// run to the next, so that goldens can be compared exactly on one machine.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
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
#include "support/render_command_fixture.h"
#include "support/video_probe.h"

namespace {

namespace fs = std::filesystem;
using rugosim::Image;
using rugosim::read_png_file;
using rugosim::testing::probe_video;
using rugosim::testing::program;
using rugosim::testing::source_dir;
using rugosim::testing::VideoProbe;

using rugosim::testing::figure12a;

using rugosim::testing::read_text;

using rugosim::testing::Outcome;
using rugosim::testing::wait_for;

// Changes to the child's environment: a value sets the variable, nullopt removes it.
using Environment = std::map<std::string, std::optional<std::string>>;

// This process's environment with `changes` applied.
std::vector<std::string> child_environment(const Environment& changes) {
  std::vector<std::string> entries;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    if (changes.count(name) == 0) entries.push_back(entry);
  }
  for (const auto& [name, value] : changes) {
    if (value) entries.push_back(std::string(name).append("=").append(*value));
  }
  return entries;
}

// Each test in its own folder, kept when the test fails (its path is printed), removed
// otherwise.
class Determinism : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           std::string("rugosim_determinism_").append(std::to_string(::getpid())) / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
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

  // Runs `rugosim ARGS...` with the environment changed by `changes`, stdout discarded and
  // stderr to a file of the test's folder.
  Outcome run(const std::vector<std::string>& args, const Environment& changes) {
    const fs::path err_file = dir_ / std::string("stderr_").append(std::to_string(++runs_));
    std::vector<std::string> all = {program()};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> environment = child_environment(changes);
    std::vector<char*> envp;
    for (std::string& e : environment)
      envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t pid = -1;
    const int rc = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    Outcome r;
    if (rc != 0) {
      r.err = std::string("cannot start ").append(argv[0]).append(": ").append(std::strerror(rc));
      return r;
    }
    r.code = wait_for(pid);
    r.err = read_text(err_file);
    return r;
  }

  // A new folder of the test's folder.
  fs::path folder(const std::string& name) {
    const fs::path path = dir_ / name;
    fs::create_directories(path);
    return path;
  }

  fs::path dir_;
  int runs_ = 0;
};

// The simulation must not pick up anything from the rasteriser's settings; and two runs with the
// same settings agree.
TEST_F(Determinism, SimulateCsvIsIdenticalAcrossThreadCounts) {
  const std::vector<Environment> settings = {
      {{"LP_NUM_THREADS", "0"}},
      {{"LP_NUM_THREADS", "4"}},
      {{"LP_NUM_THREADS", std::nullopt}},
      {{"LP_NUM_THREADS", "0"}},
  };
  std::vector<std::string> trajectories, events;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const fs::path out = folder(std::string("run_").append(std::to_string(i)));
    const Outcome r = run({"simulate", figure12a(), "--trajectory", (out / "A.csv").string(),
                           "--events", (out / "E.csv").string()},
                          settings[i]);
    ASSERT_EQ(r.code, 0) << "run " << i << ": " << r.err;
    trajectories.push_back(read_text(out / "A.csv"));
    events.push_back(read_text(out / "E.csv"));
  }
  // figure12a: 8 rocks over 151 frames, and hundreds of impulses as they collide and settle
  // (resting contact at mid-step writes no events: 381 at normal).
  EXPECT_GT(std::count(trajectories[0].begin(), trajectories[0].end(), '\n'), 8 * 151);
  EXPECT_GT(std::count(events[0].begin(), events[0].end(), '\n'), 300);
  for (std::size_t i = 1; i < settings.size(); ++i) {
    EXPECT_TRUE(trajectories[i] == trajectories[0]) << "trajectory of run " << i << " differs";
    EXPECT_TRUE(events[i] == events[0]) << "events of run " << i << " differ";
  }
}

// The simulation's own threads (--threads) change nothing (issue 14): the 50-body pile over
// its first second, while it lands and settles (hundreds of body pairs a step), gives the same
// bytes of trajectory and events, and of stats.json but for its wall_time, with 1, 2, 3 and 8
// threads.
TEST_F(Determinism, SimulateOutputIsIdenticalForAnyNumberOfSimulationThreads) {
  const std::string pile = (source_dir() / "scenes" / "pile_50.json").string();
  const auto without_wall_time = [](const std::string& stats) {
    std::istringstream lines(stats);
    std::string line, kept;
    while (std::getline(lines, line)) {
      if (line.find("\"wall_time\"") == std::string::npos) kept.append(line).append("\n");
    }
    return kept;
  };
  std::vector<std::string> trajectories, events, stats;
  for (const std::string threads : {"1", "2", "3", "8"}) {
    const fs::path out = folder("threads_" + threads);
    const Outcome r = run({"simulate", pile, "--duration", "1.0", "--threads", threads,
                           "--trajectory", (out / "A.csv").string(), "--events",
                           (out / "E.csv").string(), "--stats", (out / "S.json").string()},
                          {});
    ASSERT_EQ(r.code, 0) << threads << " threads: " << r.err;
    trajectories.push_back(read_text(out / "A.csv"));
    events.push_back(read_text(out / "E.csv"));
    stats.push_back(without_wall_time(read_text(out / "S.json")));
  }
  EXPECT_GT(std::count(events[0].begin(), events[0].end(), '\n'), 10000);
  EXPECT_NE(stats[0].find("\"steps\""), std::string::npos);
  for (std::size_t i = 1; i < trajectories.size(); ++i) {
    EXPECT_TRUE(trajectories[i] == trajectories[0]) << "trajectory of run " << i << " differs";
    EXPECT_TRUE(events[i] == events[0]) << "events of run " << i << " differ";
    EXPECT_EQ(stats[i], stats[0]) << "stats of run " << i << " differ";
  }
}

// Frames 40..45: the rocks are colliding, edges everywhere, so any difference in rasterisation
// order or tiling would show.
TEST_F(Determinism, RenderedFramesAreIdenticalAcrossRasteriserThreads) {
  struct Setting {
    std::string name;
    std::vector<std::string> options;
    Environment environment;
  };
  const std::vector<Setting> settings = {
      {"--gl-threads 0", {"--gl-threads", "0"}, {{"LP_NUM_THREADS", std::nullopt}}},
      {"--gl-threads 1", {"--gl-threads", "1"}, {{"LP_NUM_THREADS", std::nullopt}}},
      {"--gl-threads 4", {"--gl-threads", "4"}, {{"LP_NUM_THREADS", std::nullopt}}},
      {"LP_NUM_THREADS=3", {}, {{"LP_NUM_THREADS", "3"}}},
      {"egl, --gl-threads 0", {"--backend", "egl", "--gl-threads", "0"}, {}},
      {"egl, --gl-threads 4", {"--backend", "egl", "--gl-threads", "4"}, {}},
      {"egl, LP_NUM_THREADS=3", {"--backend", "egl"}, {{"LP_NUM_THREADS", "3"}}},
      // The pipeline's own thread count: PNG compression workers.
      {"--png-workers 1", {"--png-workers", "1"}, {{"LP_NUM_THREADS", std::nullopt}}},
      {"--png-workers 4, --gl-threads 2",
       {"--png-workers", "4", "--gl-threads", "2"},
       {{"LP_NUM_THREADS", std::nullopt}}},
  };
  std::vector<std::vector<Image>> frames;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const fs::path out = folder(std::string("run_").append(std::to_string(i)));
    std::vector<std::string> args = {"render",   figure12a(), "-o",     (out / "f_%d.png").string(),
                                     "--frames", "40:45",     "--size", "320x180"};
    args.insert(args.end(), settings[i].options.begin(), settings[i].options.end());
    const Outcome r = run(args, settings[i].environment);
    ASSERT_EQ(r.code, 0) << settings[i].name << ": " << r.err;
    frames.emplace_back();
    for (int k = 40; k <= 45; ++k) {
      frames.back().push_back(read_png_file(
          (out / std::string("f_").append(std::to_string(k)).append(".png")).string()));
    }
  }
  ASSERT_EQ(frames[0][0].width, 320);
  ASSERT_EQ(frames[0][0].height, 180);
  EXPECT_FALSE(frames[0].front().rgba == frames[0].back().rgba);  // not a still
  for (std::size_t i = 1; i < settings.size(); ++i) {
    for (std::size_t k = 0; k < frames[i].size(); ++k) {
      EXPECT_EQ(frames[i][k].width, frames[0][k].width);
      EXPECT_EQ(frames[i][k].height, frames[0][k].height);
      EXPECT_TRUE(frames[i][k].rgba == frames[0][k].rgba)
          << "frame " << 40 + k << " with " << settings[i].name << " differs from "
          << settings[0].name;
    }
  }
}

// libx264 is deterministic for a given number of encoder threads (it is run with its automatic
// count, which depends only on the machine's cores), and the MP4 muxer writes no creation time:
// two renders on one machine give the same file, byte for byte, whatever the rasteriser threads.
// (Across machines with other core counts the bytes may differ; the decoded pixels of the
// frames fed to the encoder do not: RenderedFramesAreIdenticalAcrossRasteriserThreads.)
TEST_F(Determinism, RenderedMp4IsIdenticalAcrossRuns) {
  const std::vector<std::pair<std::vector<std::string>, Environment>> settings = {
      {{"--gl-threads", "0"}, {}},
      {{"--gl-threads", "0"}, {}},
      {{}, {{"LP_NUM_THREADS", "4"}}},
  };
  std::vector<std::string> files;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const fs::path clip = dir_ / std::string("clip_").append(std::to_string(i)).append(".mp4");
    std::vector<std::string> args = {"render",   figure12a(), "-o",     clip.string(),
                                     "--frames", "0:29",      "--size", "320x180"};
    args.insert(args.end(), settings[i].first.begin(), settings[i].first.end());
    const Outcome r = run(args, settings[i].second);
    ASSERT_EQ(r.code, 0) << "run " << i << ": " << r.err;
    files.push_back(read_text(clip));
  }
  const VideoProbe probe = probe_video((dir_ / "clip_0.mp4").string());
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.frames, 30u);
  EXPECT_GT(files[0].size(), 1000u);
  for (std::size_t i = 1; i < files.size(); ++i)
    EXPECT_TRUE(files[i] == files[0]) << "clip " << i << " differs from clip 0";
}

// What the goldens of `snapshot` rely on: goldens made with one rasteriser setting and backend
// match the others exactly (--exact).
TEST_F(Determinism, SnapshotIsExactAcrossRasteriserThreadsAndBackends) {
  const fs::path golden = folder("golden");
  const std::vector<std::string> base = {"snapshot", figure12a(), "--golden", golden.string()};
  std::vector<std::string> update = base;
  update.insert(update.end(), {"--update", "--size", "192x108", "--frames", "0:150:30"});
  const Outcome written = run(update, {{"LP_NUM_THREADS", "0"}});
  ASSERT_EQ(written.code, 0) << written.err;

  std::vector<std::string> exact = base;
  exact.push_back("--exact");
  std::vector<std::string> exact_egl = exact;
  exact_egl.insert(exact_egl.end(), {"--backend", "egl"});
  for (const auto& [args, environment] :
       std::vector<std::pair<std::vector<std::string>, Environment>>{
           {exact, {{"LP_NUM_THREADS", "4"}}},
           {exact, {{"LP_NUM_THREADS", std::nullopt}}},
           {exact_egl, {{"LP_NUM_THREADS", "2"}}}}) {
    const Outcome r = run(args, environment);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("figure12a: passed (6 frames)"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(": failed"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(": passed:"), std::string::npos) << r.err;  // identical, not close
  }
}

}  // namespace
