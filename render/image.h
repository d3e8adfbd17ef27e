// A rendered frame in memory: 8-bit RGBA, rows from the top of the image down (the order of
// PNG files and video frames; GlContext::read_pixels returns it this way).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/huge_page_allocator.h"

namespace rugosim {

struct Image {
  int width = 0;   // px
  int height = 0;  // px
  // width × height × 4 bytes, row-major, top row first; a large frame in huge pages, which
  // a short render (a chunk) first touches far faster (huge_page_allocator.h)
  std::vector<std::uint8_t, HugePageAllocator<std::uint8_t>> rgba;
  // Which picture the pixels are, where their maker knows it: images with the same non-zero
  // value have the same pixels (SceneRenderer numbers its pictures from a counter of the whole
  // process), 0 means unknown. Whoever changes the pixels must set it to 0. It lets a renderer
  // skip reading back, and a sink skip converting, a picture it already holds.
  std::uint64_t picture = 0;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(bytes(w, h), 0) {}

  // Bytes of a w × h image.
  static std::size_t bytes(int w, int h) {
    return static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4;
  }
  std::size_t stride() const { return static_cast<std::size_t>(width) * 4; }  // bytes per row
  std::uint8_t* pixel(int x, int y) { return rgba.data() + offset(x, y); }
  const std::uint8_t* pixel(int x, int y) const { return rgba.data() + offset(x, y); }

 private:
  std::size_t offset(int x, int y) const {
    return static_cast<std::size_t>(y) * stride() + static_cast<std::size_t>(x) * 4;
  }
};

}  // namespace rugosim
