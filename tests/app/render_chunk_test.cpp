// render --chunk (render_chunk.h): the task index from I/N or from the engine's environment
// (Slurm, Kubernetes, GNU parallel, in that order), chunks that partition the clip, the chunk
// files' names, and the checkpoints a chunk starts from.
#include "render/app/render_chunk.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/program_under_test.h"

namespace rugosim::app {
namespace {

// Sets (or, with nullptr, unsets) the three task-index variables for one test.
class TaskEnvironment {
 public:
  TaskEnvironment(const char* slurm, const char* kubernetes, const char* parallel) {
    set("SLURM_ARRAY_TASK_ID", slurm);
    set("JOB_COMPLETION_INDEX", kubernetes);
    set("PARALLEL_SEQ", parallel);
  }
  ~TaskEnvironment() {
    for (const char* name : {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX", "PARALLEL_SEQ"})
      ::unsetenv(name);
  }

 private:
  static void set(const char* name, const char* value) {
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
};

std::string refusal(const std::string& text) {
  try {
    parse_chunk(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RenderChunk, ExplicitIndices) {
  const TaskEnvironment none(nullptr, nullptr, nullptr);
  const ChunkIndex c = parse_chunk("2/4");
  EXPECT_EQ(c.index, 2u);
  EXPECT_EQ(c.count, 4u);
  EXPECT_NE(refusal("4/4").find("below 4"), std::string::npos);
  for (const char* bad : {"", "3", "/4", "1/0", "a/4", "1/4x", "-1/4", "1 /4"})
    EXPECT_NE(refusal(bad).find("expected I/N or auto/N"), std::string::npos) << bad;
}

TEST(RenderChunk, AutoReadsSlurmThenKubernetesThenParallel) {
  {
    const TaskEnvironment all("3", "1", "1");
    EXPECT_EQ(parse_chunk("auto/4").index, 3u);  // Slurm's array index, 0-based
  }
  {
    const TaskEnvironment k8s(nullptr, "1", "1");
    EXPECT_EQ(parse_chunk("auto/4").index, 1u);  // an Indexed Job's, 0-based
  }
  {
    const TaskEnvironment gnu(nullptr, nullptr, "1");
    EXPECT_EQ(parse_chunk("auto/4").index, 0u);  // GNU parallel's job number, 1-based
  }
  {
    const TaskEnvironment none(nullptr, nullptr, nullptr);
    EXPECT_NE(refusal("auto/4").find("none of SLURM_ARRAY_TASK_ID"), std::string::npos);
  }
  {
    const TaskEnvironment zero(nullptr, nullptr, "0");
    EXPECT_NE(refusal("auto/4").find("PARALLEL_SEQ=\"0\""), std::string::npos);
  }
  {
    const TaskEnvironment past("4", nullptr, nullptr);
    EXPECT_NE(refusal("auto/4").find("below 4"), std::string::npos);
  }
}

TEST(RenderChunk, ChunksPartitionTheClipEvenly) {
  std::mt19937 random(20261204);
  for (int trial = 0; trial < 500; ++trial) {
    const std::size_t frames = 1 + random() % 5000;
    const std::size_t count = 1 + random() % frames;
    std::size_t next = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const auto [first, end] = chunk_frames({i, count}, frames);
      ASSERT_EQ(first, next) << frames << " frames, chunk " << i << " of " << count;
      ASSERT_GT(end, first);
      ASSERT_LE(end - first, frames / count + 1);
      ASSERT_GE(end - first, frames / count);
      next = end;
    }
    ASSERT_EQ(next, frames);
  }
}

TEST(RenderChunk, ChunkFileNames) {
  EXPECT_EQ(chunk_path("out/figure12a.mp4", 2), "out/figure12a.chunk2.mp4");
  EXPECT_EQ(chunk_path("clip.mp4", 0), "clip.chunk0.mp4");
  EXPECT_EQ(chunk_path("out/clip", 1), "out/clip.chunk1.mp4");
}

TEST(RenderChunk, StartsFromTheLatestCheckpointBeforeItsFirstFrame) {
  const testing::ScratchDir dir("render_chunk_start");
  const std::string scene = (testing::source_dir() / "scenes" / "figure12a.json").string();
  const std::string ck = (dir.path() / "ck").string();
  ASSERT_EQ(std::system((testing::program() + " simulate " + scene + " --checkpoints " + ck +
                         " --every 15 2>/dev/null")
                            .c_str()),
            0);
  const Checkpoint run = read_checkpoint(checkpoint_path(ck, 15));
  Checkpoint same = run;  // what run_identity gives the same scene and settings
  same.frame = 0;
  ChunkStart start = find_chunk_start(ck, same, 0, 150);
  EXPECT_FALSE(start.state);  // the clip's first chunk starts from the scene
  EXPECT_FALSE(start.clip_bounds.empty());
  start = find_chunk_start(ck, same, 45, 150);
  ASSERT_TRUE(start.state);
  EXPECT_EQ(start.state->frame, 30u);  // strictly before: frame 45 is simulated, with its events
  start = find_chunk_start(ck, same, 46, 150);
  EXPECT_EQ(start.state->frame, 45u);
  EXPECT_EQ(find_chunk_start(ck, same, 14, 150).clip_bounds.max,
            read_checkpoint(checkpoint_path(ck, 150)).bounds.max);
  // A clip of another length has no checkpoint at its last frame: the pass must be rerun.
  EXPECT_THROW(find_chunk_start(ck, same, 45, 149), CheckpointError);
  Checkpoint other = same;
  other.settings += ";other";
  EXPECT_THROW(find_chunk_start(ck, other, 45, 150), CheckpointError);
}

}  // namespace
}  // namespace rugosim::app
