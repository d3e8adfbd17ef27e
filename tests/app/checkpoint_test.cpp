// Exact checkpoints through the program (simulate --checkpoints DIR --every N, --resume FILE;
// render/app/checkpoint_file.h): a run resumed from every checkpoint (every 15 frames) of
// figure12a and of the 200-body pile writes, byte for byte, the trajectory and events of the
// single run after that frame, and its stats.json equals the single run's but for wall_time;
// corrupt, truncated, other-scene, other-settings and other-build checkpoints are refused with
// exit 2, the reason, and nothing written.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/app/checkpoint_file.h"
#include "support/program_under_test.h"

namespace rugosim::app {
namespace {

namespace fs = std::filesystem;
using testing::program;
using testing::run_command_line;
using testing::ScratchDir;
using testing::source_dir;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

std::string scene(const std::string& name) {
  return (source_dir() / "scenes" / (name + ".json")).string();
}

testing::CommandRun simulate(const fs::path& dir, const std::string& args, int guard = 600) {
  return run_command_line(program() + " simulate " + args, dir / "stderr.txt", guard);
}

// The single run with checkpoints every 15 frames, then a run resumed from each checkpoint.
void expect_resumes_match(const std::string& name) {
  ScratchDir dir("checkpoint_" + name);
  const fs::path& d = dir.path();
  const std::string outputs = " --trajectory " + (d / "traj.csv").string() + " --events " +
                              (d / "events.csv").string() + " --stats " +
                              (d / "stats.json").string();
  ASSERT_EQ(
      simulate(d, scene(name) + " --checkpoints " + (d / "ckpt").string() + " --every 15" + outputs)
          .exit_code,
      0);
  const std::vector<std::string> traj = lines(read_text(d / "traj.csv"));
  const std::vector<std::string> events = lines(read_text(d / "events.csv"));
  const nlohmann::json stats = nlohmann::json::parse(read_text(d / "stats.json"));
  std::vector<fs::path> checkpoints;
  for (const auto& entry : fs::directory_iterator(d / "ckpt"))
    checkpoints.push_back(entry.path());
  std::sort(checkpoints.begin(), checkpoints.end());
  ASSERT_GE(checkpoints.size(), 9u) << name;
  const std::size_t bodies = (traj.size() - 1) / 151;  // 151 frames of 5 s at 30 frames/s
  ASSERT_EQ(traj.size(), 1 + 151 * bodies) << name;
  for (const fs::path& checkpoint : checkpoints) {
    const std::uint64_t frame = read_checkpoint(checkpoint.string()).frame;
    ASSERT_EQ(checkpoint, fs::path(checkpoint_path((d / "ckpt").string(), frame)));
    fs::path resumed = d / ("resumed_" + std::to_string(frame));
    fs::create_directories(resumed);
    const std::string resumed_outputs = " --trajectory " + (resumed / "traj.csv").string() +
                                        " --events " + (resumed / "events.csv").string() +
                                        " --stats " + (resumed / "stats.json").string();
    ASSERT_EQ(simulate(resumed, scene(name) + " --resume " + checkpoint.string() + resumed_outputs)
                  .exit_code,
              0)
        << read_text(resumed / "stderr.txt");
    const std::vector<std::string> rt = lines(read_text(resumed / "traj.csv"));
    ASSERT_EQ(rt.front(), traj.front());
    // The rows of every frame after the checkpoint's, exactly.
    const std::vector<std::string> expected(
        traj.begin() + static_cast<std::ptrdiff_t>(1 + (frame + 1) * bodies), traj.end());
    EXPECT_EQ(std::vector<std::string>(rt.begin() + 1, rt.end()), expected)
        << name << " resumed at frame " << frame;
    const std::vector<std::string> re = lines(read_text(resumed / "events.csv"));
    ASSERT_LE(re.size(), events.size());
    EXPECT_EQ(
        std::vector<std::string>(re.begin() + 1, re.end()),
        std::vector<std::string>(events.end() - static_cast<long>(re.size() - 1), events.end()))
        << name << " resumed at frame " << frame;
    nlohmann::json rs = nlohmann::json::parse(read_text(resumed / "stats.json"));
    nlohmann::json full = stats;
    rs.erase("wall_time");
    full.erase("wall_time");
    EXPECT_EQ(rs, full) << name << " resumed at frame " << frame;
  }
}

TEST(Checkpoints, Figure12aResumesExactlyFromEveryCheckpoint) {
  expect_resumes_match("figure12a");
}

TEST(Checkpoints, Pile200ResumesExactlyFromEveryCheckpoint) {
  expect_resumes_match("pile_200");
}

TEST(Checkpoints, EncodingRoundTripsAndRefusesDamage) {
  Checkpoint c;
  c.program_version = "0.1.0";
  c.build = "abc";
  c.scene_hash = 42;
  c.settings = "max_step=0.001;fps=30";
  c.frame = 15;
  c.time = 0.5;
  c.state_hash = 7;
  c.world_state = std::string("\0\1state", 7);
  const std::string bytes = encode_checkpoint(c);
  const Checkpoint back = decode_checkpoint(bytes);
  EXPECT_EQ(back.world_state, c.world_state);
  EXPECT_EQ(back.frame, 15u);
  EXPECT_EQ(incompatibility(back, c), "");
  const auto refusal = [](const std::string& b) {
    try {
      decode_checkpoint(b);
    } catch (const CheckpointError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("{\"scene\": 1}"), "not a rugosim checkpoint");
  for (std::size_t cut : {bytes.size() / 2, bytes.size() - 1, std::size_t{25}}) {
    EXPECT_NE(refusal(bytes.substr(0, cut)).find("truncated"), std::string::npos) << cut;
  }
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x10;
  EXPECT_NE(refusal(flipped).find("corrupt"), std::string::npos);

  Checkpoint other = c;
  other.build = "def";
  EXPECT_NE(incompatibility(other, c).find("build def"), std::string::npos);
  other = c;
  other.scene_hash = 43;
  EXPECT_NE(incompatibility(other, c).find("another scene"), std::string::npos);
  other = c;
  other.settings = "max_step=0.002;fps=30";
  EXPECT_NE(incompatibility(other, c).find("other settings"), std::string::npos);
}

// Each refused checkpoint: exit 2, the reason on stderr, no output file created.
TEST(Checkpoints, RefusedCheckpointsWriteNothing) {
  ScratchDir dir("checkpoint_refusals");
  const fs::path& d = dir.path();
  ASSERT_EQ(simulate(d, scene("figure12a") + " --duration 1 --checkpoints " +
                            (d / "ckpt").string() + " --every 15")
                .exit_code,
            0);
  const fs::path good = checkpoint_path((d / "ckpt").string(), 15);
  const std::string bytes = read_text(good);
  std::string corrupt = bytes;
  corrupt[bytes.size() / 2] ^= 0x01;
  write_text(d / "corrupt.ckpt", corrupt);
  write_text(d / "truncated.ckpt", bytes.substr(0, bytes.size() / 2));
  Checkpoint other_build = read_checkpoint(good.string());
  other_build.program_version = "0.0.9";
  write_text(d / "other_version.ckpt", encode_checkpoint(other_build));

  struct Case {
    std::string args;
    std::string reason;
  };
  const std::vector<Case> cases = {
      {scene("figure12a") + " --resume " + (d / "corrupt.ckpt").string(), "corrupt"},
      {scene("figure12a") + " --resume " + (d / "truncated.ckpt").string(), "corrupt or truncated"},
      {scene("figure12a") + " --resume " + (d / "other_version.ckpt").string(),
       "written by rugosim 0.0.9"},
      {scene("figure12b") + " --resume " + good.string(), "another scene"},
      {scene("figure12a") + " --max-step 0.002 --resume " + good.string(), "other settings"},
      {scene("figure12a") + " --fps 60 --resume " + good.string(), "other settings"},
      {scene("figure12a") + " --duration 0.4 --resume " + good.string(), "past the run's last"},
      {scene("figure12a") + " --resume " + (d / "missing.ckpt").string(), "cannot be read"},
  };
  for (const Case& c : cases) {
    const fs::path out = d / "out";
    const testing::CommandRun run =
        simulate(d, c.args + " --trajectory " + (out / "t.csv").string() + " --stats " +
                        (out / "s.json").string() + " --checkpoints " + (out / "ck").string());
    EXPECT_EQ(run.exit_code, 2) << c.args << "\n" << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(c.reason), std::string::npos) << c.args << "\n"
                                                                 << run.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << c.args << " created output";
  }
}

}  // namespace
}  // namespace rugosim::app
