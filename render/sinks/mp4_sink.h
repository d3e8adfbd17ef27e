// MP4 clips of the rendered frames: H.264 through libx264 (yuv420p, BT.709 limited range, the
// tags and the RGB → YUV matrix agreeing so players show the rendered colours) in a FRAGMENTED
// MP4 (empty moov, one fragment per keyframe). Fragments reach the file as soon as they are
// complete, so a render killed at any point (even by SIGKILL) leaves a playable clip that lacks
// only the frames of the open fragment and those still inside the encoder:
//   lost frames < keyframe_interval + encoder delay,
// where the encoder delay is x264's lookahead (which x264 caps at keyframe_interval), its
// B-frames and about one frame per frame thread. With the defaults that is one to two seconds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim {

struct Mp4Options {
  double fps = 30;                // frames per second of video, finite and > 0
  int crf = 18;                   // x264 constant rate factor, 0 (lossless) .. 51
  std::string preset = "medium";  // an x264 preset (mp4_preset_is_valid)
  int keyframe_interval = 0;      // frames, >= 0; 0 = one keyframe per second, round(fps)
  int threads = 0;                // x264 threads, >= 0; 0 = x264 chooses from the core count
  // x264's stitchable: the stream's headers do not depend on its frames, so that clips encoded
  // apart with the same settings can be concatenated into one stream (render --chunk, join).
  bool stitchable = false;
  // Written as the file's "comment" metadata when not empty (render --chunk: which render a
  // chunk belongs to; mp4_comment reads it back).
  std::string comment{};
};

// Sets FFmpeg's process-wide log level to errors only (libx264 otherwise prints its settings and
// statistics on stderr): for programs that report progress themselves.
void quiet_ffmpeg_logs();

// The x264 presets: ultrafast superfast veryfast faster fast medium slow slower veryslow placebo.
bool mp4_preset_is_valid(std::string_view preset);
// 0 ..= 51.
bool mp4_crf_is_valid(int crf);

class Mp4Sink final : public FrameSink {
 public:
  // Opens `path` (a file system path, also /dev/... or a named pipe; never read as an FFmpeg
  // URL, so a ':' in it is harmless), starts the encoder and writes the MP4 header at once, so
  // a path that cannot be written fails here, before any rendering: SinkError with the path, the
  // step and FFmpeg's reason (e.g. "No such file or directory", "No space left on device").
  // Throws std::invalid_argument for options out of range or a size that is not positive and
  // even ("MP4 needs an even width and height, got 321x240"): yuv420p halves both sides for
  // the chroma planes, and padding would change the picture the user asked for.
  Mp4Sink(std::string path, int width, int height, const Mp4Options& options = {});
  ~Mp4Sink() override;  // closes, swallowing errors: call close() to hear about them
  Mp4Sink(const Mp4Sink&) = delete;
  Mp4Sink& operator=(const Mp4Sink&) = delete;

  // Encodes one frame (alpha is ignored). Frames get consecutive timestamps whatever `index`
  // says, so the clip lasts frames_written() / fps seconds. A frame numbered with the picture
  // of the one before (Image::picture) is not converted again. Throws SinkError for a frame whose
  // size differs from the sink's (or whose pixel buffer does not match its size), for an
  // encoder or I/O failure, and after close().
  void write(const Image& frame, std::size_t index) override;
  // Drains the encoder, writes the trailer and closes the file; reports a write error that the
  // I/O layer held back until now (e.g. a full disk) as SinkError; after a write() that threw,
  // it reports that the clip is incomplete the same way. Either way the file is closed and
  // everything freed. Idempotent: after the first call (even one that threw) it does nothing.
  void close() override;
  // Frames handed to the encoder.
  std::size_t frames_written() const override { return frames_written_; }

  const std::string& path() const { return path_; }
  int keyframe_interval() const { return keyframe_interval_; }  // frames, after defaulting

 private:
  struct Encoder;  // the libav objects, kept out of this header

  std::string path_;
  int width_;              // px
  int height_;             // px
  int keyframe_interval_;  // frames
  std::size_t frames_written_ = 0;
  std::uint64_t converted_picture_ = 0;  // Image::picture of the frame's YUV, 0 if unknown
  std::unique_ptr<Encoder> encoder_;     // null once closed
};

}  // namespace rugosim
