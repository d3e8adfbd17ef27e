#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "engine/core/byte_stream.h"
#include "engine/dynamics/state_hash.h"
#include "engine/dynamics/telemetry.h"
#include "engine/scene/scene_world.h"
#include "render/app/atomic_file.h"
#include "render/app/checkpoint_file.h"
#include "render/app/commands.h"
#include "render/app/crossing_report.h"
#include "render/app/progress.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"

namespace rugosim::app {
namespace {

// Text for an AtomicFile, written out in chunks so memory stays bounded on long runs.
class BufferedOutput {
 public:
  explicit BufferedOutput(const std::string& path)
      : file_(path.empty() ? nullptr : std::make_unique<AtomicFile>(path)) {}
  std::string* buffer() { return file_ ? &text_ : nullptr; }
  void flush_if_large() {
    if (file_ && text_.size() > (1u << 20)) flush();
  }
  void commit() {
    if (!file_) return;
    flush();
    file_->commit();
  }

 private:
  void flush() {
    file_->write(text_);
    text_.clear();
  }
  std::unique_ptr<AtomicFile> file_;
  std::string text_;
};

// Restores the World from the checkpoint at `path`; returns it, or nullopt after
// printing why it cannot be resumed here.
std::optional<Checkpoint> resume(World& world, const std::string& path, const Checkpoint& run,
                                 std::size_t last) {
  try {
    Checkpoint saved = read_checkpoint(path);
    if (const std::string why = incompatibility(saved, run); !why.empty()) {
      fmt::print(stderr, "error: {}: {}\n", path, why);
      return std::nullopt;
    }
    if (saved.frame > last) {
      fmt::print(stderr, "error: {}: frame {} is past the run's last frame, {}\n", path,
                 saved.frame, last);
      return std::nullopt;
    }
    world.restore_state(saved.world_state);
    if (full_state_hash(world) != saved.state_hash) {
      throw CheckpointError(path + ": corrupt (the restored state's hash differs from the saved)");
    }
    return saved;
  } catch (const CheckpointError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
  } catch (const ByteStreamError& e) {
    fmt::print(stderr, "error: {}: corrupt ({})\n", path, e.what());
  }
  return std::nullopt;
}

}  // namespace

int run_simulate(const SimulateOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy, o.threads);
  if (!loaded) return kExitUsage;
  World& world = *loaded->world;
  const double duration = o.duration.value_or(loaded->scene.duration);
  const double fps = o.fps.value_or(loaded->scene.render.fps);
  // Frames k = 0..last at t = k / fps, up to the duration.
  const RunFrames run = run_frames(duration, o.duration ? "--duration" : "world.duration", fps,
                                   o.fps ? "--fps" : "render.fps", world.settings().min_step);
  if (!run.error.empty()) {
    fmt::print(stderr, "error: {}\n", run.error);
    return kExitUsage;
  }
  const std::size_t last = run.last;
  const Accuracy accuracy = scene_accuracy(loaded->scene);

  try {
    // The run's identity (the scene file read again and hashed) and the framing box are only
    // for checkpoints: a plain run pays for neither.
    const bool checkpoints = !o.checkpoint_dir.empty();
    const Checkpoint run_id = checkpoints || !o.resume_path.empty()
                                  ? run_identity(o.scene_path, accuracy, fps)
                                  : Checkpoint{};
    // A checkpoint is checked, and the World restored, before any output exists: a refused one
    // leaves nothing written.
    std::size_t first = 1;
    Aabb resumed_bounds;
    if (!o.resume_path.empty()) {
      const std::optional<Checkpoint> from = resume(world, o.resume_path, run_id, last);
      if (!from) return kExitUsage;
      first = from->frame + 1;
      resumed_bounds = from->bounds;
    }
    // The automatic camera's framing (fit_clip_camera): every body's box over the frames so far.
    Aabb bounds = first == 1 ? Aabb{} : resumed_bounds;
    const auto frame_bounds = [&] {
      if (!checkpoints) return;
      for (std::size_t i = 0; i < world.body_count(); ++i)
        bounds.extend(world.body(i).shape().world_bounds(world.body(i).placement()));
    };
    if (first == 1) frame_bounds();
    const auto write_checkpoint = [&](std::size_t frame) {
      if (!checkpoints) return;
      // Made with the first checkpoint, after every output opened: a bad path leaves nothing.
      std::filesystem::create_directories(o.checkpoint_dir);
      Checkpoint c = run_id;
      c.frame = frame;
      c.time = world.time();
      c.last_frame = last;
      c.bounds = bounds;
      c.state_hash = full_state_hash(world);
      c.world_state = world.save_state();
      write_text_atomically(checkpoint_path(o.checkpoint_dir, frame), encode_checkpoint(c));
    };
    // Every output is created before the run, so a bad path fails at once.
    BufferedOutput trajectory(o.trajectory_path);
    BufferedOutput events(o.events_path);
    std::unique_ptr<AtomicFile> stats_file =
        o.stats_path.empty() ? nullptr : std::make_unique<AtomicFile>(o.stats_path);
    if (std::string* t = trajectory.buffer()) {
      t->append(kTrajectoryCsvHeader);
      if (o.resume_path.empty()) append_trajectory_rows(*t, world, 0);
    }
    if (std::string* e = events.buffer()) e->append(kEventsCsvHeader);

    // A clip of one frame has its last checkpoint at frame 0.
    if (last == 0 && first == 1) write_checkpoint(0);
    const SigintGuard sigint;
    world.set_stop_flag(&SigintGuard::interrupted());
    CrossingWatch crossings;
    Progress progress(static_cast<double>(last) / fps, stderr);
    std::size_t frame = first;
    for (; frame <= last && !sigint.interrupted(); ++frame) {
      world.advance_to(static_cast<double>(frame) / fps);
      crossings.check(world, stderr);
      if (sigint.interrupted()) break;  // the World stopped short of the frame's time
      if (std::string* t = trajectory.buffer()) append_trajectory_rows(*t, world, frame);
      if (std::string* e = events.buffer()) {
        for (const ContactEvent& event : world.events())
          append_event_row(*e, world, event);
      }
      world.clear_events();
      frame_bounds();
      // At every `every`-th frame, and at the last: its box frames the whole clip.
      if (frame % o.every == 0 || frame == last) write_checkpoint(frame);
      trajectory.flush_if_large();
      events.flush_if_large();
      progress.update(world.time());
    }
    progress.finish();
    const double wall = progress.wall_seconds();
    trajectory.commit();
    events.commit();
    if (stats_file) {
      stats_file->write(stats_json(world.stats(), wall, &accuracy, &world));
      stats_file->commit();
    }
    const StepStats& s = world.stats();
    fmt::print(stderr,
               "{}: {:.4g} s simulated in {:.3g} s wall ({} frames): {} steps, {} bisections, "
               "{} collisions, {} contacts, {} fallbacks, {} crossings\n",
               sigint.interrupted() ? "interrupted" : "done", world.time(), wall, frame, s.steps,
               s.bisections, s.collisions, s.contacts, s.fallbacks, s.crossings);
    return strict_exit_code(world, o.strict, sigint.interrupted() ? kExitInterrupted : kExitOk,
                            stderr);
  } catch (const std::runtime_error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
