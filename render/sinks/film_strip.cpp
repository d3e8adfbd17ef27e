#include "render/sinks/film_strip.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace rugosim {
namespace {

// i·span/d exactly needs more than 64 bits when the range is huge.
__extension__ typedef unsigned __int128 Wide;

std::string size_text(const Image& image) {
  return std::to_string(image.width).append("×").append(std::to_string(image.height));
}

bool well_formed(const Image& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgba.size() == std::size_t{4} * static_cast<std::size_t>(image.width) *
                                  static_cast<std::size_t>(image.height);
}

}  // namespace

Image compose_film_grid(std::span<const Image> frames, const StripGrid& grid,
                        std::array<std::uint8_t, 4> background) {
  if (frames.empty()) throw std::invalid_argument("film strip: no frames");
  if (grid.gap_px < 0 || grid.label_px < 0 || grid.columns < 0) {
    throw std::invalid_argument(
        std::string("film strip: the gap, the label band and the columns must be 0 or more, got ")
            .append(std::to_string(grid.gap_px))
            .append(", ")
            .append(std::to_string(grid.label_px))
            .append(", ")
            .append(std::to_string(grid.columns)));
  }
  const Image& first = frames.front();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Image& frame = frames[i];
    if (!well_formed(frame)) {
      throw std::invalid_argument(
          std::string("film strip: frame ")
              .append(std::to_string(i))
              .append(" is empty or its pixels do not hold width × height × 4 bytes"));
    }
    if (frame.width != first.width || frame.height != first.height) {
      throw std::invalid_argument(std::string("film strip: frame ")
                                      .append(std::to_string(i))
                                      .append(" is ")
                                      .append(size_text(frame))
                                      .append(", expected ")
                                      .append(size_text(first))
                                      .append(" as frame 0"));
    }
  }
  const auto n = static_cast<long long>(frames.size());
  const long long columns = grid.columns == 0 ? n : std::min<long long>(grid.columns, n);
  const long long rows = (n + columns - 1) / columns;
  const long long width = columns * first.width + (columns - 1) * grid.gap_px;
  const long long height =
      rows * (first.height + grid.label_px) + (rows - 1) * static_cast<long long>(grid.gap_px);
  if (width > std::numeric_limits<int>::max() || height > std::numeric_limits<int>::max() ||
      width * height > std::numeric_limits<int>::max() / 4) {
    throw std::invalid_argument("film strip: too large for one image");
  }
  Image strip(static_cast<int>(width), static_cast<int>(height));
  for (std::size_t i = 0; i < strip.rgba.size(); i += 4)
    std::memcpy(strip.rgba.data() + i, background.data(), 4);
  const std::size_t frame_row = first.stride();
  const StripGrid used{static_cast<int>(columns), grid.gap_px, grid.label_px};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto [x, y] = grid_cell(used, first.width, first.height, i, frames.size());
    for (int row = 0; row < first.height; ++row)
      std::memcpy(strip.pixel(x, y + row), frames[i].pixel(0, row), frame_row);
  }
  return strip;
}

std::array<int, 2> grid_cell(const StripGrid& grid, int frame_width, int frame_height,
                             std::size_t i, std::size_t count) {
  const std::size_t columns =
      grid.columns == 0 ? count : std::min(static_cast<std::size_t>(grid.columns), count);
  const auto column = static_cast<int>(i % columns);
  const auto row = static_cast<int>(i / columns);
  return {column * (frame_width + grid.gap_px), row * (frame_height + grid.label_px + grid.gap_px)};
}

Image compose_film_strip(std::span<const Image> frames, int gap_px,
                         std::array<std::uint8_t, 4> gap_colour) {
  return compose_film_grid(frames, StripGrid{0, gap_px, 0}, gap_colour);
}

std::vector<std::size_t> strip_frame_indices(std::size_t first, std::size_t last,
                                             std::size_t count) {
  if (first > last) {
    throw std::invalid_argument(std::string("film strip: the first frame ")
                                    .append(std::to_string(first))
                                    .append(" is after the last ")
                                    .append(std::to_string(last)));
  }
  const std::size_t span = last - first;
  std::vector<std::size_t> indices;
  if (count == 0) return indices;
  if (count == 1) {
    indices.push_back(first + span / 2 + span % 2);
    return indices;
  }
  // Every frame when there are no more than asked for (span + 1 <= count, without overflow).
  if (span < count) {
    indices.reserve(span + 1);
    for (std::size_t k = 0; k <= span; ++k)
      indices.push_back(first + k);
    return indices;
  }
  // Here span ≥ count > d, so consecutive exact positions are at least 1 apart and their
  // roundings strictly increase.
  const std::size_t d = count - 1;
  indices.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Wide twice = Wide{2} * i * span + d;  // round(i·span/d), halves up
    indices.push_back(first + static_cast<std::size_t>(twice / (Wide{2} * d)));
  }
  return indices;
}

}  // namespace rugosim
