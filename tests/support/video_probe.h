// What a video file holds, found by decoding all of it with libavformat/libavcodec: a test's
// independent look at what the MP4 sink wrote (frames are counted by decoding, not taken from
// the container's metadata).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "render/image.h"

namespace rugosim::testing {

struct VideoProbe {
  std::string codec;       // FFmpeg's codec name, e.g. "h264"
  int width = 0;           // px
  int height = 0;          // px
  std::size_t frames = 0;  // frames the decoder returned
  double duration_s = 0;   // s, from the packets: end of the last (pts + duration) - first pts
  double fps = 0;          // frames per second, as the container states it
  std::vector<Image> decoded_rgba;  // every frame in display order, only when asked
};

// Throws std::runtime_error naming the file when it cannot be opened, has no video stream, or
// its video cannot be decoded. Pixels are converted to RGBA with the matrix and range the
// stream is tagged with (BT.601 when untagged).
VideoProbe probe_video(const std::string& path, bool decode_pixels = false);

}  // namespace rugosim::testing
