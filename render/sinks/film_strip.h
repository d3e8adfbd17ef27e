// A film strip: a few frames of a clip side by side in one image, to show a motion at a glance
// (the paper's figures of a body bouncing down a slope are drawn this way).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "render/image.h"

namespace rugosim {

// The frames left to right, `gap_px` columns of `gap_colour` (RGBA) between neighbours and
// none at the ends: width n·w + (n − 1)·gap_px, height h. Throws std::invalid_argument when
// there are no frames, when a frame is empty, malformed or not the size of the first, when
// gap_px < 0, or when the strip would be wider than an int holds.
Image compose_film_strip(std::span<const Image> frames, int gap_px,
                         std::array<std::uint8_t, 4> gap_colour);

// `count` frame numbers spread evenly over [first, last], both ends included when count ≥ 2:
// frame i is first + i·(last − first)/(count − 1) rounded to nearest, halves up (so (0, 149, 5)
// gives 0, 37, 75, 112, 149). Strictly increasing; when the range holds no more than `count`
// frames, every frame of it. count == 1 gives the middle frame, first + (last − first)/2 with
// halves rounded up; count == 0 nothing. Throws std::invalid_argument when first > last.
std::vector<std::size_t> strip_frame_indices(std::size_t first, std::size_t last,
                                             std::size_t count);

}  // namespace rugosim
