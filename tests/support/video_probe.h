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

// How the file may end. A fragmented MP4 whose writer was killed outright can end part way
// through its last fragment: players play the fragments before it and stop there.
enum class FileEnd {
  complete,    // every sample the container lists must be whole and decode
  may_be_cut,  // a sample the file ends inside is the cut tail: not decoded
};

// Throws std::runtime_error naming the file when it cannot be opened, has no video stream, or
// its video cannot be decoded (with FileEnd::may_be_cut: a sample wholly inside the file that
// does not decode, or a read error before the end of the file). Pixels are converted to RGBA with
// the matrix and range the stream is tagged with (BT.601 when untagged), alpha kept where the
// stream has it (VP9 is decoded by libvpx-vp9 for that).
VideoProbe probe_video(const std::string& path, bool decode_pixels = false,
                       FileEnd end = FileEnd::complete);

}  // namespace rugosim::testing
