#include "render/app/checkpoint_file.h"

#include <utility>

#include <fmt/core.h>

#include "engine/core/byte_stream.h"
#include "engine/core/hash.h"
#include "engine/core/version.h"
#include "render/app/atomic_file.h"
#include "render/app/build_id.h"

namespace rugosim::app {
namespace {

constexpr std::string_view kMagic = "RUGOSIM-CHECKPOINT\n";
constexpr std::uint64_t kFormat = 1;

std::uint64_t bytes_hash(std::string_view bytes) {
  Fnv1a hash;
  hash.add_bytes(bytes.data(), bytes.size());
  return hash.value();
}

std::string read_bytes(const std::string& path) {
  std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) throw CheckpointError(path + ": cannot be read");
  return std::move(*bytes);
}

}  // namespace

std::uint64_t file_hash(const std::string& path) {
  return bytes_hash(read_bytes(path));
}

Checkpoint run_identity(const std::string& scene_path, const Accuracy& accuracy, double fps) {
  Checkpoint c;
  c.program_version = kVersion;
  c.build = build_id();
  c.scene_hash = file_hash(scene_path);
  for (const AccuracyKnob& knob : accuracy_knobs())
    c.settings += fmt::format("{}={};", knob.key, knob.get(accuracy));
  c.settings += fmt::format("fps={}", fps);
  return c;
}

std::string encode_checkpoint(const Checkpoint& c) {
  ByteWriter out;
  out.u64(kFormat);
  out.text(c.program_version);
  out.text(c.build);
  out.u64(c.scene_hash);
  out.text(c.settings);
  out.u64(c.frame);
  out.f64(c.time);
  out.u64(c.last_frame);
  for (const double v : {c.bounds.min.x(), c.bounds.min.y(), c.bounds.max.x(), c.bounds.max.y()})
    out.f64(v);
  out.u64(c.state_hash);
  out.text(c.world_state);
  std::string bytes = std::string(kMagic) + out.bytes();
  ByteWriter sum;
  sum.u64(bytes_hash(bytes));
  return bytes + sum.bytes();
}

Checkpoint decode_checkpoint(const std::string& bytes) {
  if (bytes.compare(0, kMagic.size(), kMagic) != 0)
    throw CheckpointError("not a rugosim checkpoint");
  if (bytes.size() < kMagic.size() + 16) throw CheckpointError("truncated");
  const std::string_view body(bytes.data(), bytes.size() - 8);
  if (ByteReader(std::string_view(bytes).substr(bytes.size() - 8)).u64() != bytes_hash(body)) {
    throw CheckpointError("corrupt or truncated (its checksum does not match its contents)");
  }
  try {
    ByteReader in(body.substr(kMagic.size()));
    const std::uint64_t format = in.u64();
    if (format != kFormat) {
      throw CheckpointError(
          fmt::format("of format {}; this program reads format {}", format, kFormat));
    }
    Checkpoint c;
    c.program_version = in.text();
    c.build = in.text();
    c.scene_hash = in.u64();
    c.settings = in.text();
    c.frame = in.u64();
    c.time = in.f64();
    c.last_frame = in.u64();
    const double x0 = in.f64(), y0 = in.f64(), x1 = in.f64(), y1 = in.f64();
    c.bounds.min = Vec2(x0, y0);
    c.bounds.max = Vec2(x1, y1);
    c.state_hash = in.u64();
    c.world_state = in.text();
    if (!in.at_end()) throw CheckpointError("corrupt (bytes after its contents)");
    return c;
  } catch (const ByteStreamError& e) {
    throw CheckpointError(std::string("corrupt (") + e.what() + ")");
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  try {
    return decode_checkpoint(read_bytes(path));
  } catch (const CheckpointError& e) {
    const std::string what = e.what();
    if (what.rfind(path, 0) == 0) throw;
    throw CheckpointError(fmt::format("{}: {}", path, what));
  }
}

std::string incompatibility(const Checkpoint& saved, const Checkpoint& current) {
  if (saved.program_version != current.program_version || saved.build != current.build) {
    return fmt::format("written by rugosim {} (build {}), not by this rugosim {} (build {})",
                       saved.program_version, saved.build, current.program_version, current.build);
  }
  if (saved.scene_hash != current.scene_hash) {
    return fmt::format(
        "written for another scene file (its bytes hash to {:016x}, this one's to "
        "{:016x})",
        saved.scene_hash, current.scene_hash);
  }
  if (saved.settings != current.settings) {
    return fmt::format("written with other settings ({}), not these ({})", saved.settings,
                       current.settings);
  }
  return {};
}

std::string checkpoint_path(const std::string& dir, std::uint64_t frame) {
  return fmt::format("{}/frame_{:06d}.ckpt", dir, frame);
}

}  // namespace rugosim::app
