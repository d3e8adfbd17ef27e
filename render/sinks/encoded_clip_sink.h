// Clips for slides, web pages and video editors, written whole when complete: animated GIF,
// WebM (VP9), MOV (ProRes 4444) and animated WebP. Each takes RGBA frames (alpha kept where the
// format can hold it, when the sink is opened with `alpha`) through an FFmpeg filter graph that
// makes the encoder's pixels, then FFmpeg's encoder and muxer:
//   GIF   one 256-colour palette for the whole clip (palettegen over every frame, then
//         paletteuse with error diffusion redone only where a frame changed); 1-bit alpha
//         (a pixel under half opaque is transparent); loops forever. Delays are whole
//         centiseconds, frame k at round(100·k/fps) cs, and browsers slow delays under 2 cs to
//         10 cs: at most 50 frames per second. The palette needs every frame, so the frames
//         are held in the filter graph (about width × height × 4 bytes each) until close().
//   WebM  VP9 (libvpx) at constant quality, yuv420p, or yuva420p with alpha (the alpha plane
//         travels beside the colour, which FFmpeg's own VP9 decoder drops: decode with
//         libvpx-vp9 to see it); BT.709 limited range, tagged.
//   MOV   ProRes 4444 (prores_ks), yuv444p10, or yuva444p10 with alpha: for video editors.
//   WebP  animated WebP (libwebp), lossy at quality 90, with alpha; loops forever; delays in
//         milliseconds.
// The file goes to a temporary file beside the target that replaces it only when complete: a
// failed or killed render leaves any earlier file as it was. A target that is a device or a
// pipe is written directly. The filters run on the caller's thread, the encoder and the muxer
// on a thread of the sink's own (so that filtering a frame overlaps encoding the one before):
// a failure there (a full disk) is reported by the next write() or by close(). The same
// frames make the same file, byte for byte.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim {

enum class ClipFormat { kGif, kWebm, kMov, kWebp };

// "gif", "webm", "mov", "webp" and back.
std::optional<ClipFormat> parse_clip_format(std::string_view name);
std::string_view clip_format_name(ClipFormat format);

struct ClipOptions {
  double fps = 30;     // frames per second: finite, > 0 (GIF: at most 50)
  bool alpha = false;  // keep the frames' alpha (false: opaque, alpha ignored)
};

// Whether `format` can play `fps` frames per second: GIF at most 50, the others any finite fps
// above 0 up to 1000.
bool clip_fps_is_valid(ClipFormat format, double fps);

class EncodedClipSink final : public FrameSink {
 public:
  // Opens the temporary file (so a folder that is not there, or a file that cannot be written,
  // fails here, before any rendering: SinkError naming `path` and the reason) and sets up the
  // filters, the encoder and the muxer. Throws std::invalid_argument for a size outside
  // 1..16384 a side or an fps that clip_fps_is_valid refuses.
  EncodedClipSink(std::string path, ClipFormat format, int width, int height,
                  const ClipOptions& options = {});
  ~EncodedClipSink() override;  // without close(): the temporary file goes, the target stays
  EncodedClipSink(const EncodedClipSink&) = delete;
  EncodedClipSink& operator=(const EncodedClipSink&) = delete;

  // Hands one frame to the filters and queues the result for the encoder (waiting while two
  // frames are queued). Frames get consecutive times whatever `index` says. Throws SinkError
  // for a frame of another size, a filter failure, an encoder or muxer failure met since the
  // last call, and after close().
  void write(const Image& frame, std::size_t index) override;
  // Finishes the encoding, writes the trailer and puts the file in place. After a write()
  // that threw, or with no frame written, it reports that as SinkError and leaves the target
  // untouched. Idempotent.
  void close() override;
  std::size_t frames_written() const override { return frames_written_; }

  const std::string& path() const { return path_; }

 private:
  struct Encoder;  // the libav objects, kept out of this header

  std::string path_;
  ClipFormat format_;
  int width_;   // px
  int height_;  // px
  double fps_;
  std::size_t frames_written_ = 0;
  bool failed_ = false;
  std::unique_ptr<Encoder> encoder_;  // null once closed
};

}  // namespace rugosim
