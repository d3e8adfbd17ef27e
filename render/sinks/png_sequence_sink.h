// Frames as numbered PNG files ("out/f_%04d.png"), compressed on worker threads: encoding is
// the bottleneck at 1080p (about 14 ms a frame at the default settings on one core), so the
// renderer hands frames to a small bounded queue and goes on drawing while the workers
// compress and write. Two workers on two cores: about 100–120 frames/s of 1920×1080.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "render/image.h"
#include "render/sinks/frame_sink.h"
#include "render/sinks/png_io.h"

namespace rugosim {

// True when `pattern` holds exactly one integer conversion — %d, %Nd or %0Nd with N of one or
// two digits (no leading zero in N) — and every other '%' is written "%%".
bool is_png_pattern(std::string_view pattern);

// The pattern with its conversion replaced by `index` as printf would write it (padded with
// spaces to N characters for %Nd, zeros for %0Nd; never truncated) and "%%" by "%". Parsed
// here, never passed to printf. Throws std::invalid_argument when !is_png_pattern(pattern).
std::string format_frame_path(std::string_view pattern, std::size_t index);

class PngSequenceSink final : public FrameSink {
 public:
  // The frame numbered k goes to format_frame_path(pattern, k), written atomically
  // (write_png_file). Throws std::invalid_argument for a bad pattern (or one whose number is
  // in the directory part, or workers < 1) and SinkError when the pattern's directory does not
  // exist.
  PngSequenceSink(std::string pattern, PngSettings settings = {}, int workers = 2);
  // Waits for the workers (close()), swallowing any error.
  ~PngSequenceSink() override;
  PngSequenceSink(const PngSequenceSink&) = delete;
  PngSequenceSink& operator=(const PngSequenceSink&) = delete;

  // Copies the frame into the queue; blocks while the queue is full. Throws SinkError with the
  // first failure of any worker (that and every later write() and close(): once a file failed
  // the sink writes no more) or after close(), std::invalid_argument for an empty or malformed
  // image.
  void write(const Image& frame, std::size_t index) override;
  // Waits until every queued frame is written and stops the workers. Throws SinkError as
  // write() does.
  void close() override;
  // Files completely written (renamed into place) so far; after close() without error, the
  // number of write() calls.
  std::size_t frames_written() const override;

  const std::string& pattern() const { return pattern_; }

 private:
  struct Job {
    Image image;
    std::size_t index = 0;
  };

  void work();
  void stop_workers();

  std::string pattern_;
  PngSettings settings_;
  std::size_t capacity_;  // queued frames at most

  mutable std::mutex mutex_;
  std::condition_variable work_ready_;   // a job was queued, or the workers must stop
  std::condition_variable space_ready_;  // a job was taken from the queue
  std::deque<Job> queue_;
  std::vector<Image> spare_;  // buffers of finished jobs, reused to skip allocation and faults
  bool stopping_ = false;
  bool closed_ = false;
  std::string error_;  // the first failure; empty while all is well
  std::size_t written_ = 0;
  std::vector<std::thread> workers_;
};

}  // namespace rugosim
