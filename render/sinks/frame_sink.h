// Where rendered frames go, in order: a PNG sequence or an MP4 clip (DESIGN.md, "FrameSink").
// A sink may be fed from a thread other than the one that made it, but from one thread at a
// time.
#pragma once

#include <cstddef>
#include <stdexcept>

#include "render/image.h"

namespace rugosim {

// An I/O or encoder failure: the message names the file and says what went wrong (the program
// exits 1 on it).
class SinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Writes the frame numbered `index` in the scene (with --frames A:B the first is A). Every
  // frame has the size the sink was opened with. Throws SinkError.
  virtual void write(const Image& frame, std::size_t index) = 0;
  // Finishes the output (flushes the encoder, writes trailers) so that it is complete and
  // readable; also after an interruption. Idempotent. Throws SinkError.
  virtual void close() = 0;
  // Frames written so far.
  virtual std::size_t frames_written() const = 0;
};

}  // namespace rugosim
