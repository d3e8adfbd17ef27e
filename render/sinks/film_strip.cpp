#include "render/sinks/film_strip.h"

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

Image compose_film_strip(std::span<const Image> frames, int gap_px,
                         std::array<std::uint8_t, 4> gap_colour) {
  if (frames.empty()) throw std::invalid_argument("film strip: no frames");
  if (gap_px < 0) {
    throw std::invalid_argument(std::string("film strip: the gap must be 0 or more pixels, got ")
                                    .append(std::to_string(gap_px)));
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
  const long long width = n * first.width + (n - 1) * gap_px;
  if (frames.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      width > std::numeric_limits<int>::max()) {
    throw std::invalid_argument("film strip: too wide for one image");
  }
  Image strip(static_cast<int>(width), first.height);
  const std::size_t frame_row = first.stride();
  for (int y = 0; y < strip.height; ++y) {
    std::uint8_t* out = strip.pixel(0, y);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      if (i > 0) {
        for (int g = 0; g < gap_px; ++g, out += 4)
          std::memcpy(out, gap_colour.data(), 4);
      }
      std::memcpy(out, frames[i].pixel(0, y), frame_row);
      out += frame_row;
    }
  }
  return strip;
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
