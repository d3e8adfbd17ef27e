// Mesh chunks (mesh_chunks.h): a body's triangles split into runs that cover each triangle
// once, in order, with boxes that hold their vertices; a selection keeps the order and joins
// neighbouring runs.
#include "render/draw/mesh_chunks.h"

#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

// Vertex v at (v, 2v): easy to check the boxes.
Aabb point_of(std::uint32_t v) {
  Aabb box;
  box.extend(Vec2(static_cast<double>(v), 2.0 * v));
  return box;
}

TEST(MeshChunks, ChunksCoverEveryTriangleOnceInOrder) {
  std::vector<std::uint32_t> indices;
  for (std::uint32_t i = 0; i < 3 * 100; ++i)
    indices.push_back(i % 37);
  std::vector<MeshChunk> chunks;
  append_chunks(chunks, 4, indices, 30, 3 * 70, point_of, 16);  // triangles 10..79
  ASSERT_EQ(chunks.size(), 5u);                                 // 16 + 16 + 16 + 16 + 6
  std::uint32_t next = 30;
  for (const MeshChunk& c : chunks) {
    EXPECT_EQ(c.body, 4u);
    EXPECT_EQ(c.first, next);
    EXPECT_EQ(c.count % 3, 0u);
    for (std::uint32_t i = c.first; i < c.first + c.count; ++i) {
      EXPECT_TRUE(c.bounds.contains(point_of(indices[i]).min)) << i;
    }
    next += c.count;
  }
  EXPECT_EQ(next, 30u + 210u);
  EXPECT_THROW(append_chunks(chunks, 0, indices, 0, 4, point_of), std::invalid_argument);
  EXPECT_THROW(append_chunks(chunks, 0, indices, 297, 6, point_of), std::invalid_argument);
}

TEST(MeshChunks, SelectionKeepsOrderAndJoinsNeighbours) {
  std::vector<MeshChunk> chunks(5);
  for (std::uint32_t i = 0; i < 5; ++i) {
    chunks[i].first = 6 * i;
    chunks[i].count = 6;
  }
  // Chunks 0, 1, 3 and 4 meet the rectangle, 2 does not.
  const std::vector<PixelRect> placed = {
      {0, 0, 10, 10}, {5, 5, 20, 20}, {50, 50, 60, 60}, {8, 8, 9, 9}, {0, 9, 100, 10}};
  EXPECT_EQ(select_chunks(chunks, placed, {0, 0, 12, 12}),
            (std::vector<IndexRange>{{0, 12}, {18, 12}}));
  EXPECT_TRUE(select_chunks(chunks, placed, {200, 200, 300, 300}).empty());
  // Chunk rectangles are placed by their body's placement.
  chunks[2].body = 1;
  chunks[2].bounds.extend(Vec2(0.0, 0.0));
  Camera camera;
  camera.height = 1.0;
  camera.width_px = 100;
  camera.height_px = 100;
  const std::vector<Transform2> placements = {Transform2(), Transform2(0.0, Vec2(0.25, 0.0))};
  const std::vector<PixelRect> moved = place_chunks(chunks, placements, camera, 1);
  EXPECT_TRUE(moved[0].empty());  // an empty box covers nothing
  EXPECT_EQ(moved[2], (PixelRect{74, 49, 77, 52}));
}

}  // namespace
}  // namespace rugosim
