#include "render/app/render_chunk.h"

#include <charconv>
#include <cstdlib>
#include <filesystem>

#include <fmt/core.h>

#include "render/app/task_index.h"

namespace rugosim::app {

ChunkIndex parse_chunk(const std::string& text) {
  const std::size_t slash = text.find('/');
  // 0 for a count that is missing or not a whole number (0 chunks is refused too).
  const std::size_t count =
      slash == std::string::npos ? 0 : whole_number(text.substr(slash + 1)).value_or(0);
  const std::string index_text = slash == std::string::npos ? text : text.substr(0, slash);
  const std::optional<std::size_t> index =
      index_text == "auto" ? std::optional<std::size_t>(0) : whole_number(index_text);
  if (!index || count == 0) {
    throw std::invalid_argument(
        fmt::format("--chunk: expected I/N or auto/N (0 <= I < N), got \"{}\"", text));
  }
  const ChunkIndex chunk{
      index_text == "auto" ? task_index_from_environment("--chunk auto") : *index, count};
  if (chunk.index >= chunk.count) {
    throw std::invalid_argument(
        fmt::format("--chunk {}: the index must be below {} (0-based)", text, chunk.count));
  }
  return chunk;
}

std::pair<std::size_t, std::size_t> chunk_frames(const ChunkIndex& chunk, std::size_t frames) {
  return {chunk.index * frames / chunk.count, (chunk.index + 1) * frames / chunk.count};
}

std::string chunk_path(const std::string& output, std::size_t index) {
  std::filesystem::path path(output);
  const std::string stem =
      path.extension() == ".mp4" ? path.stem().string() : path.filename().string();
  return (path.parent_path() / fmt::format("{}.chunk{}.mp4", stem, index)).string();
}

std::string chunk_tag(const ChunkIndex& chunk, std::uint64_t render) {
  return fmt::format("rugosim chunk {}/{} {:016x}", chunk.index, chunk.count, render);
}

std::optional<ChunkTag> parse_chunk_tag(const std::string& comment) {
  constexpr std::string_view kPrefix = "rugosim chunk ";
  if (comment.rfind(kPrefix, 0) != 0) return std::nullopt;
  const std::string rest = comment.substr(kPrefix.size());
  const std::size_t slash = rest.find('/');
  const std::size_t space = rest.find(' ');
  if (slash == std::string::npos || space == std::string::npos || space < slash)
    return std::nullopt;
  const std::optional<std::size_t> index = whole_number(std::string_view(rest).substr(0, slash));
  const std::optional<std::size_t> count =
      whole_number(std::string_view(rest).substr(slash + 1, space - slash - 1));
  if (!index || !count) return std::nullopt;
  return ChunkTag{{*index, *count}, rest.substr(space + 1)};
}

ChunkStart find_chunk_start(const std::string& dir, const Checkpoint& run, std::size_t first,
                            std::size_t last) {
  const auto usable = [&](std::size_t frame) -> std::optional<Checkpoint> {
    const std::string path = checkpoint_path(dir, frame);
    if (!std::filesystem::exists(path)) return std::nullopt;
    Checkpoint c = read_checkpoint(path);
    if (const std::string why = incompatibility(c, run); !why.empty())
      throw CheckpointError(fmt::format("{}: {}", path, why));
    if (c.frame != frame || c.last_frame != last) {
      throw CheckpointError(fmt::format(
          "{}: written at frame {} of a clip of {} frames, not at frame {} of this clip of {}",
          path, c.frame, c.last_frame + 1, frame, last + 1));
    }
    return c;
  };
  ChunkStart start;
  const std::optional<Checkpoint> end = usable(last);
  if (!end) {
    throw CheckpointError(fmt::format(
        "{}: no checkpoint at the clip's last frame ({}): run the checkpoint pass first "
        "(rugosim simulate SCENE --checkpoints {} with the same settings)",
        checkpoint_path(dir, last), last, dir));
  }
  start.clip_bounds = end->bounds;
  // The chunk's first frame must be simulated (its events and contacts are those since the frame
  // before), so the state is taken from a checkpoint strictly before it.
  for (std::size_t frame = first; frame-- > 1;) {
    if (std::optional<Checkpoint> c = usable(frame)) {
      start.state = std::move(c);
      break;
    }
  }
  return start;
}

}  // namespace rugosim::app
