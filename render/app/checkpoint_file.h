// Checkpoint files (simulate --checkpoints DIR --every N, --resume FILE; INTERFACE.md): a
// World's exact state at a frame boundary (World::save_state) with what it must be resumed
// with, so that a resumed run gives, bit for bit, the frames of the run that wrote it.
//
// Layout (format 1; integers little-endian, doubles as bit patterns, texts as a 64-bit length
// and bytes): the magic "RUGOSIM-CHECKPOINT\n", the format, the program's version and build
// (its git commit), the scene file's hash (FNV-1a of its bytes), the settings that shape the
// steps (every accuracy knob's value after the command line's overrides, and the frame rate),
// the frame and its time, the run's last frame, the box around every body over the frames so far
// (the automatic camera's framing: at the last frame, of the whole clip, so that a chunk of a
// render never simulates the clip to place its camera), the full state hash
// (full_state_hash), the World's state, and last a
// checksum (FNV-1a of every byte before it). Anything else is refused with the reason: not a
// checkpoint, another format, truncated, corrupt (checksum), another program build, another
// scene, other settings.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "engine/core/aabb.h"
#include "engine/dynamics/accuracy.h"

namespace rugosim::app {

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Checkpoint {
  std::string program_version;  // kVersion
  std::string build;            // build_id()
  std::uint64_t scene_hash = 0;
  std::string settings;  // "key=value;…": the accuracy knobs and the frame rate
  std::uint64_t frame = 0;
  double time = 0.0;             // s, the World's time at that frame
  std::uint64_t last_frame = 0;  // the last frame of the run that wrote it
  Aabb bounds;                   // m: every body's world box over frames 0..frame
  std::uint64_t state_hash = 0;
  std::string world_state;  // World::save_state()
};

// What a checkpoint of a run must match to be resumed by it: this program's version and build,
// the scene file's hash, and the settings that shape the steps (every accuracy knob after the
// command line's overrides, and the frame rate; not the duration, so that a resumed run may go
// on further, nor the threads, which change nothing). The other fields are left empty.
Checkpoint run_identity(const std::string& scene_path, const Accuracy& accuracy, double fps);

// FNV-1a of a file's bytes; throws CheckpointError naming the file when it cannot be read.
std::uint64_t file_hash(const std::string& path);

// The checkpoint's bytes, checksum included.
std::string encode_checkpoint(const Checkpoint& checkpoint);
// Throws CheckpointError: not a checkpoint, another format, truncated, or corrupt.
Checkpoint decode_checkpoint(const std::string& bytes);
// Reads and decodes; errors name the file.
Checkpoint read_checkpoint(const std::string& path);

// Empty when `saved` may be resumed by this program on the scene and settings of `current`
// (its state is not looked at); else why not, in a sentence.
std::string incompatibility(const Checkpoint& saved, const Checkpoint& current);

// "DIR/frame_000045.ckpt".
std::string checkpoint_path(const std::string& dir, std::uint64_t frame);

}  // namespace rugosim::app
