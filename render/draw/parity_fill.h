// Triangles whose coverage parity is a closed outline's inside (even-odd rule), for filling any
// simple or self-touching polygon by XOR (shaders/body_fill.frag) without triangulating it.
//
// A plain fan from one anchor would do, but its triangles reach across the whole body: a
// software rasteriser bins every triangle into every tile it touches, and thousands of long
// slivers cost more than the pixels they cover. So the fan is hierarchical: the outline's
// points are thinned by a stride (every 8th, every 64th, ...) until few remain; the anchor fans
// over the coarsest ring, and each edge of a ring gets a small fan over the finer points it
// cuts off. Parity composes: a point's parity for the outline is the XOR of its parities for
// the coarse ring and for every cap between a coarse edge and its finer points.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.h"

namespace rugosim {

struct ParityFill {
  // Three per triangle: i < outline.size() is outline point i, i == outline.size() the anchor.
  std::vector<std::uint32_t> indices;
  Vec2 anchor = Vec2::Zero();  // the mean of the coarsest ring's points
};

// Fewer than 3 points give no triangles.
ParityFill parity_fill(std::span<const Vec2> outline, std::size_t stride = 8);

}  // namespace rugosim
