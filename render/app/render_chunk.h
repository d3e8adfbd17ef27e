// A render split into chunks of frames (render --chunk I/N --checkpoints DIR; docs/scale-out.md):
// chunk I of N draws its share of the clip's frames, starting from the latest checkpoint before
// its first frame (written by `simulate --checkpoints DIR`), with the automatic camera framed
// from the checkpoint at the clip's last frame, so that no chunk simulates what comes before
// its checkpoint or after its frames. Each chunk is its own MP4 (OUT.chunkI.mp4), which
// `rugosim join` concatenates.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/core/aabb.h"
#include "render/app/checkpoint_file.h"

namespace rugosim::app {

struct ChunkIndex {
  std::size_t index = 0;  // 0-based
  std::size_t count = 1;
};

// "I/N" (0 <= I < N), or "auto/N": I from the environment of the engine running the task, the
// first set of SLURM_ARRAY_TASK_ID (0-based, as submitted with --array=0-(N-1)),
// JOB_COMPLETION_INDEX (a Kubernetes Indexed Job, 0-based) and PARALLEL_SEQ (GNU parallel,
// 1-based: minus one). Throws std::invalid_argument with the reason.
ChunkIndex parse_chunk(const std::string& text);

// Frames [first, end) of the chunk among `frames` frames 0..frames-1: contiguous shares that
// differ in size by at most one.
std::pair<std::size_t, std::size_t> chunk_frames(const ChunkIndex& chunk, std::size_t frames);

// "out/clip.mp4" → "out/clip.chunk2.mp4".
std::string chunk_path(const std::string& output, std::size_t index);

// The tag each chunk's MP4 carries as its comment: "rugosim chunk I/N <render>", where <render>
// (16 hex digits) hashes the checkpoints' run identity and every option that shapes the frames,
// so that a rerun skips only a chunk of the same render and join refuses chunks of others.
std::string chunk_tag(const ChunkIndex& chunk, std::uint64_t render);
struct ChunkTag {
  ChunkIndex chunk;
  std::string render;
};
// nullopt for a comment that is not a chunk tag.
std::optional<ChunkTag> parse_chunk_tag(const std::string& comment);

struct ChunkStart {
  std::optional<Checkpoint> state;  // the latest before `first`; none: start from the scene
  Aabb clip_bounds;                 // every body's box over the whole clip
};

// Reads DIR's checkpoints (frame_NNNNNN.ckpt) of the run `run` (run_identity): the latest one
// before `first` and the one at `last`, the clip's last frame. Throws CheckpointError when DIR
// holds no checkpoint at `last`, or one that this run may not resume (the reason, the file).
ChunkStart find_chunk_start(const std::string& dir, const Checkpoint& run, std::size_t first,
                            std::size_t last);

}  // namespace rugosim::app
