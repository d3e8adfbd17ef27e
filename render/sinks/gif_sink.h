// Animated GIF clips of the rendered frames, for slides and web pages: one 256-colour palette
// built for the whole clip (FFmpeg's palettegen over every frame, then paletteuse with
// error-diffusion dithering re-done only where a frame changed), looping forever.
//
// GIF delays are whole centiseconds: frame k starts at round(100·k/fps) cs, so 30 fps plays as
// delays of 3 and 4 cs that keep the clip's length. Browsers slow delays under 2 cs to 10 cs,
// hence at most 50 frames per second (gif_fps_is_valid).
//
// The palette needs every frame, so the frames are held (in FFmpeg's filter graph, about
// width × height × 4 bytes each) and the file is written by close(). It goes to a temporary
// file beside the target that replaces it only when complete: a failed or killed render leaves
// any earlier file as it was. A target that is a device or a pipe is written directly. Alpha is
// ignored (the frames are opaque).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim {

struct GifOptions {
  double fps = 30;  // frames per second, in (0, 50]
};

// fps in (0, 50].
bool gif_fps_is_valid(double fps);

class GifSink final : public FrameSink {
 public:
  // Opens the temporary file (so a folder that is not there, or a file that cannot be written,
  // fails here, before any rendering: SinkError naming `path` and the reason) and sets up the
  // palette filters and the encoder. Throws std::invalid_argument for a size outside 1..65535
  // a side or an fps that gif_fps_is_valid refuses.
  GifSink(std::string path, int width, int height, const GifOptions& options = {});
  ~GifSink() override;  // without close(): the temporary file is removed, the target untouched
  GifSink(const GifSink&) = delete;
  GifSink& operator=(const GifSink&) = delete;

  // Hands one frame to the palette filters. Frames get consecutive times whatever `index`
  // says. Throws SinkError for a frame of another size, a filter failure, and after close().
  void write(const Image& frame, std::size_t index) override;
  // Builds the palette, encodes every frame, writes the trailer and puts the file in place.
  // After a write() that threw, or with no frame written, it reports that as SinkError and
  // leaves the target untouched. Idempotent.
  void close() override;
  std::size_t frames_written() const override { return frames_written_; }

  const std::string& path() const { return path_; }

 private:
  struct Encoder;  // the libav objects, kept out of this header

  std::string path_;
  int width_;   // px
  int height_;  // px
  double fps_;
  std::size_t frames_written_ = 0;
  bool failed_ = false;
  std::unique_ptr<Encoder> encoder_;  // null once closed
};

}  // namespace rugosim
