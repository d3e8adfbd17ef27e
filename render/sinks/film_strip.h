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

// How the frames of a strip are laid out: in rows of `columns` (0: one row of all), `gap_px`
// apart across and down, each with a band of `label_px` under it (for its time label).
struct StripGrid {
  int columns = 0;
  int gap_px = 0;
  int label_px = 0;
};

// The frames in reading order on a grid, the gaps, bands and any empty cells of the last row
// in `background` (RGBA): width c·w + (c − 1)·gap, height r·(h + label) + (r − 1)·gap for c
// columns and r rows. Throws std::invalid_argument when there are no frames, when a frame is
// empty, malformed or not the size of the first, when the gap, band or columns are negative,
// or when the image would be larger than an int holds a side.
Image compose_film_grid(std::span<const Image> frames, const StripGrid& grid,
                        std::array<std::uint8_t, 4> background);

// The top left corner (x, y) of frame i's cell, for `count` frames of `frame_width` px.
std::array<int, 2> grid_cell(const StripGrid& grid, int frame_width, int frame_height,
                             std::size_t i, std::size_t count);

// One row, no bands: compose_film_grid(frames, {0, gap_px, 0}, gap_colour).
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
