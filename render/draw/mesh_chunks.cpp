#include "render/draw/mesh_chunks.h"

#include <algorithm>
#include <stdexcept>

namespace rugosim {

void append_chunks(std::vector<MeshChunk>& chunks, std::uint32_t body,
                   std::span<const std::uint32_t> indices, std::uint32_t first, std::uint32_t count,
                   const std::function<Aabb(std::uint32_t)>& reach,
                   std::uint32_t triangles_per_chunk) {
  if (count % 3 != 0 || std::size_t{first} + count > indices.size()) {
    throw std::invalid_argument("mesh chunks: the range is not whole triangles of the mesh");
  }
  const std::uint32_t step = 3 * std::max<std::uint32_t>(triangles_per_chunk, 1);
  for (std::uint32_t start = first; start < first + count; start += step) {
    MeshChunk chunk;
    chunk.body = body;
    chunk.first = start;
    chunk.count = std::min(step, first + count - start);
    for (std::uint32_t i = start; i < start + chunk.count; ++i)
      chunk.bounds.extend(reach(indices[i]));
    chunks.push_back(chunk);
  }
}

std::vector<PixelRect> place_chunks(std::span<const MeshChunk> chunks,
                                    std::span<const Transform2> placements, const Camera& camera,
                                    int margin_px) {
  std::vector<PixelRect> placed;
  placed.reserve(chunks.size());
  for (const MeshChunk& chunk : chunks) {
    placed.push_back(window_rect(chunk.bounds, placements[chunk.body], camera, margin_px));
  }
  return placed;
}

std::vector<IndexRange> select_chunks(std::span<const MeshChunk> chunks,
                                      std::span<const PixelRect> placed, const PixelRect& rect) {
  std::vector<IndexRange> ranges;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    if (!rects_overlap(placed[i], rect)) continue;
    const MeshChunk& chunk = chunks[i];
    if (!ranges.empty() && ranges.back().first + ranges.back().count == chunk.first) {
      ranges.back().count += chunk.count;
    } else {
      ranges.push_back({chunk.first, chunk.count});
    }
  }
  return ranges;
}

}  // namespace rugosim
