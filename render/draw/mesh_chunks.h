// Runs of consecutive triangles of one body, each with bounds in the body's frame, so that
// redrawing part of a frame (dirty_rects.h) draws only the triangles that can reach it. A
// selection keeps the triangles' order (outlines are blended, so order matters) and joins
// neighbouring runs into one range per draw.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "engine/core/aabb.h"
#include "engine/core/transform.h"
#include "render/draw/camera.h"
#include "render/draw/dirty_rects.h"

namespace rugosim {

struct MeshChunk {
  std::uint32_t body = 0;
  std::uint32_t first = 0;  // first index, into the mesh's index buffer
  std::uint32_t count = 0;  // indices: three per triangle
  Aabb bounds;              // m, body frame: holds every point the triangles can cover
};

struct IndexRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  friend bool operator==(const IndexRange&, const IndexRange&) = default;
};

// Appends the chunks of one body's triangles `indices[first, first + count)` (three per
// triangle), at most `triangles_per_chunk` each; `reach(v)` gives the body-frame box that
// vertex v can cover (its point, or more where the shader moves it).
void append_chunks(std::vector<MeshChunk>& chunks, std::uint32_t body,
                   std::span<const std::uint32_t> indices, std::uint32_t first, std::uint32_t count,
                   const std::function<Aabb(std::uint32_t)>& reach,
                   std::uint32_t triangles_per_chunk = 32);

// The chunks placed for one frame: each chunk's window rectangle.
std::vector<PixelRect> place_chunks(std::span<const MeshChunk> chunks,
                                    std::span<const Transform2> placements, const Camera& camera,
                                    int margin_px);

// The index ranges, in order, of the chunks whose window rectangle (from place_chunks) meets
// `rect`; consecutive chunks come out as one range.
std::vector<IndexRange> select_chunks(std::span<const MeshChunk> chunks,
                                      std::span<const PixelRect> placed, const PixelRect& rect);

}  // namespace rugosim
