// Concatenating MP4 clips without re-encoding (rugosim join; render --chunk): each input holds
// one H.264 stream encoded with the same settings and x264's stitchable option (Mp4Options), so
// the streams' headers (SPS, PPS) are identical and each clip starts on an IDR frame; their
// packets are copied into one fragmented MP4 (kFragmentedMovFlags), each clip's timestamps
// shifted to start where the previous one ended. The decoded frames are the inputs' frames, in
// order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rugosim {

struct JoinedClip {
  std::size_t frames = 0;
  double seconds = 0.0;  // the joined stream's duration
};

// The "comment" metadata of the MP4 at `path` (Mp4Options::comment); empty when it has none.
// Throws SinkError naming the file when it cannot be read as a clip.
std::string mp4_comment(const std::string& path);

// Writes `output` from `inputs` (in order). Throws SinkError naming the input or the output:
// an input that cannot be read or holds no H.264 video stream, an input whose size, codec or
// stream headers differ from the first's (encoded with other settings: the names of both), or
// a write failure.
JoinedClip join_mp4(const std::vector<std::string>& inputs, const std::string& output);

}  // namespace rugosim
