// rugosim join OUT --chunks N: the chunks of a render split across machines (render --chunk),
// concatenated into OUT as encoded (render/sinks/mp4_join.h).
#include <filesystem>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <system_error>
#include <vector>

#include <fmt/core.h>

#include "render/app/atomic_file.h"
#include "render/app/commands.h"
#include "render/app/render_chunk.h"
#include "render/app/scene_input.h"
#include "render/sinks/frame_sink.h"
#include "render/sinks/mp4_join.h"
#include "render/sinks/mp4_sink.h"

namespace rugosim::app {

int run_join(const JoinOptions& o) {
  std::vector<std::string> chunks;
  quiet_ffmpeg_logs();
  std::string render;  // every chunk's tag must name the same render (render_chunk.h)
  for (std::size_t i = 0; i < o.chunks; ++i) {
    chunks.push_back(chunk_path(o.output, i));
    std::error_code error;
    if (!std::filesystem::is_regular_file(chunks.back(), error)) {
      fmt::print(stderr, "error: {}: chunk {} of {} is missing (render it with --chunk {}/{})\n",
                 chunks.back(), i, o.chunks, i, o.chunks);
      return kExitUsage;
    }
    std::optional<ChunkTag> tag;
    try {
      tag = parse_chunk_tag(mp4_comment(chunks.back()));
    } catch (const SinkError& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return kExitUsage;
    }
    if (!tag || tag->chunk.index != i || tag->chunk.count != o.chunks ||
        (i > 0 && tag->render != render)) {
      fmt::print(stderr,
                 "error: {}: not chunk {} of {} of the same render as {} (rendered with "
                 "--chunk {}/{} and the same scene, settings, options and build)\n",
                 chunks.back(), i, o.chunks, chunks.front(), i, o.chunks);
      return kExitUsage;
    }
    render = tag->render;
  }
  struct stat info {};
  if (!o.overwrite && ::stat(o.output.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    fmt::print(stderr, "error: {} exists; add -y to overwrite it\n", o.output);
    return kExitUsage;
  }
  std::string temporary;
  try {
    RenamedFile file(o.output);
    temporary = file.temporary();
    const JoinedClip joined = join_mp4(chunks, file.temporary());
    file.commit();
    fmt::print(stderr, "done: {} chunks joined into {}: {} frames, {:.4g} s\n", o.chunks, o.output,
               joined.frames, joined.seconds);
    return kExitOk;
  } catch (const SinkError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    // A chunk that is not a clip of the others is the user's to fix; a write failure is not.
    const bool output_failed = std::string(e.what()).rfind(temporary, 0) == 0;
    return output_failed ? kExitFailure : kExitUsage;
  } catch (const std::runtime_error& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
