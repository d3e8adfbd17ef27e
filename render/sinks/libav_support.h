// What the FFmpeg sinks share: FFmpeg's error text, owners that free libav objects on every
// path, and an options dictionary.
#pragma once

#include <string>

#include "render/sinks/frame_sink.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
#include <libavutil/frame.h>
#include <libswscale/swscale.h>
}

namespace rugosim {

// The MP4 muxer's flags of every MP4 we write (Mp4Sink, join_mp4): one fragment per keyframe,
// the moov written up front with no samples (so the file is playable before the trailer
// exists), and fragment offsets relative to their own moof (what browsers and the ISO BMFF
// readers expect).
inline constexpr const char* kFragmentedMovFlags = "frag_keyframe+empty_moov+default_base_moof";

// FFmpeg's words for an error code ("No space left on device"), or "error N".
std::string av_error_text(int code);

struct FormatContextFree {
  void operator()(AVFormatContext* format) const {
    avio_closep(&format->pb);  // null when never opened or already closed
    avformat_free_context(format);
  }
};
struct CodecContextFree {
  void operator()(AVCodecContext* codec) const { avcodec_free_context(&codec); }
};
struct FrameFree {
  void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};
struct PacketFree {
  void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
struct ScalerFree {
  void operator()(SwsContext* scaler) const { sws_freeContext(scaler); }
};

// How a sink writing `path` reports a failure: SinkError("<path>: <what>: <FFmpeg's reason>").
struct LibavErrors {
  std::string path;

  [[noreturn]] void fail(const std::string& what, int code) const;
  [[noreturn]] void fail(const std::string& what) const;
  void check(int code, const std::string& what) const {
    if (code < 0) fail(what, code);
  }
  // The AVIO layer remembers a failed write in pb->error (and drops later writes) rather than
  // returning it from the call that buffered the data; flushing is where it surfaces.
  void flush_io(AVIOContext* pb, const std::string& what) const;
};

// An AVDictionary of options, freed on every path.
class Dictionary {
 public:
  Dictionary() = default;
  ~Dictionary() { av_dict_free(&entries_); }
  Dictionary(const Dictionary&) = delete;
  Dictionary& operator=(const Dictionary&) = delete;
  AVDictionary** address() { return &entries_; }
  int count() const { return av_dict_count(entries_); }

 private:
  AVDictionary* entries_ = nullptr;
};

}  // namespace rugosim
