// What an animated WebP holds, decoded with libwebp's demux API (WebPAnimDecoder): FFmpeg 5.1
// cannot decode animated WebP, so the tests read what the WebP sink wrote with libwebp itself.
#pragma once

#include <string>
#include <vector>

#include "render/image.h"

namespace rugosim::testing {

struct WebpProbe {
  int width = 0;                // px, the canvas
  int height = 0;               // px
  int loop_count = -1;          // 0: forever
  std::vector<int> timestamps;  // ms, the end of each frame (libwebp's convention)
  std::vector<Image> frames;    // RGBA, straight alpha, the whole canvas
};

// Throws std::runtime_error naming the file when it cannot be read or decoded.
WebpProbe probe_webp(const std::string& path);

}  // namespace rugosim::testing
