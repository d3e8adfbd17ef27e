#include "render/sinks/png_sequence_sink.h"

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <sys/stat.h>
#include <utility>

namespace rugosim {
namespace {

// Where the one integer conversion of a pattern is, and how to write the number.
struct Conversion {
  std::size_t begin = 0;  // index of its '%'
  std::size_t end = 0;    // one past its 'd'
  std::size_t width = 0;  // characters at least
  bool zero_pad = false;
};

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// The conversion starting at pattern[at] == '%' (not "%%"), or nullopt when it is not %d,
// %Nd or %0Nd with N of 1 or 2 digits and no leading zero.
std::optional<Conversion> parse_conversion(std::string_view pattern, std::size_t at) {
  Conversion conversion;
  conversion.begin = at;
  std::size_t i = at + 1;
  if (i < pattern.size() && pattern[i] == '0') {
    conversion.zero_pad = true;
    ++i;
  }
  const std::size_t digits_begin = i;
  while (i < pattern.size() && is_digit(pattern[i]) && i - digits_begin < 3)
    ++i;
  const std::size_t digits = i - digits_begin;
  if (digits > 2 || (conversion.zero_pad && digits == 0)) return std::nullopt;
  if (digits > 0 && pattern[digits_begin] == '0') return std::nullopt;
  if (i >= pattern.size() || pattern[i] != 'd') return std::nullopt;
  for (std::size_t k = digits_begin; k < i; ++k) {
    conversion.width = conversion.width * 10 + static_cast<std::size_t>(pattern[k] - '0');
  }
  conversion.end = i + 1;
  return conversion;
}

// The single conversion of a valid pattern; nullopt when the pattern is not valid.
std::optional<Conversion> find_conversion(std::string_view pattern) {
  std::optional<Conversion> found;
  for (std::size_t i = 0; i < pattern.size();) {
    if (pattern[i] != '%') {
      ++i;
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      i += 2;
      continue;
    }
    const std::optional<Conversion> conversion = parse_conversion(pattern, i);
    if (!conversion || found) return std::nullopt;
    found = conversion;
    i = conversion->end;
  }
  return found;
}

// Literal text of a pattern without conversions: "%%" becomes "%".
std::string unescape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out.push_back(text[i]);
    if (text[i] == '%' && i + 1 < text.size() && text[i + 1] == '%') ++i;
  }
  return out;
}

std::string bad_pattern_message(std::string_view pattern) {
  return std::string("PNG pattern \"")
      .append(pattern)
      .append(
          "\": expected one frame-number conversion %d, %Nd or %0Nd (N of 1 or 2 digits) in the "
          "file name, e.g. out/f_%04d.png, and %% for a literal %");
}

}  // namespace

bool is_png_pattern(std::string_view pattern) {
  return find_conversion(pattern).has_value();
}

std::string format_frame_path(std::string_view pattern, std::size_t index) {
  const std::optional<Conversion> conversion = find_conversion(pattern);
  if (!conversion) throw std::invalid_argument(bad_pattern_message(pattern));
  const std::string number = std::to_string(index);
  std::string path = unescape(pattern.substr(0, conversion->begin));
  if (number.size() < conversion->width) {
    path.append(conversion->width - number.size(), conversion->zero_pad ? '0' : ' ');
  }
  path.append(number);
  path.append(unescape(pattern.substr(conversion->end)));
  return path;
}

PngSequenceSink::PngSequenceSink(std::string pattern, PngSettings settings, int workers)
    : pattern_(std::move(pattern)),
      settings_(settings),
      // One frame waiting per worker: enough to keep them busy while the renderer draws the
      // next, few enough that memory stays at a handful of frames.
      capacity_(static_cast<std::size_t>(workers > 0 ? workers : 1)) {
  const std::optional<Conversion> conversion = find_conversion(pattern_);
  if (!conversion) throw std::invalid_argument(bad_pattern_message(pattern_));
  const std::size_t slash = pattern_.rfind('/');
  if (slash != std::string::npos && slash > conversion->begin) {
    throw std::invalid_argument(
        std::string(bad_pattern_message(pattern_)).append(" (the number is in the directory)"));
  }
  if (workers < 1) {
    throw std::invalid_argument(std::string("PNG sequence \"")
                                    .append(pattern_)
                                    .append("\": expected at least 1 worker thread, got ")
                                    .append(std::to_string(workers)));
  }
  if (settings_.level < 0 || settings_.level > 9) {
    throw std::invalid_argument(std::string("PNG sequence \"")
                                    .append(pattern_)
                                    .append("\": expected a compression level 0..9, got ")
                                    .append(std::to_string(settings_.level)));
  }
  if (slash != std::string::npos) {
    const std::string directory = slash == 0 ? "/" : unescape(pattern_.substr(0, slash));
    struct stat status {};
    if (::stat(directory.c_str(), &status) != 0) {
      throw SinkError(std::string(directory)
                          .append(": ")
                          .append(std::strerror(errno))
                          .append(" (the directory of the PNG pattern)"));
    }
    if (!S_ISDIR(status.st_mode)) {
      throw SinkError(
          std::string(directory).append(": not a directory (the directory of the PNG pattern)"));
    }
  }
  // Every buffer in circulation (queued, being written, being filled by write()) comes back
  // here, so pushing a spare never allocates on a worker.
  spare_.reserve(capacity_ + static_cast<std::size_t>(workers) + 1);
  workers_.reserve(static_cast<std::size_t>(workers));
  try {
    for (int i = 0; i < workers; ++i)
      workers_.emplace_back([this] { work(); });
  } catch (...) {
    stop_workers();
    throw;
  }
}

PngSequenceSink::~PngSequenceSink() {
  try {
    close();
  } catch (...) {
    // Errors were the caller's to see from close(); a destructor must not throw.
  }
}

void PngSequenceSink::write(const Image& frame, std::size_t index) {
  if (frame.width <= 0 || frame.height <= 0 ||
      frame.rgba.size() != std::size_t{4} * static_cast<std::size_t>(frame.width) *
                               static_cast<std::size_t>(frame.height)) {
    throw std::invalid_argument(std::string(pattern_).append(
        ": a frame must be non-empty with width × height × 4 bytes of RGBA"));
  }
  Job job;
  job.index = index;
  {
    std::unique_lock lock(mutex_);
    if (closed_) throw SinkError(std::string(pattern_).append(": write after close"));
    space_ready_.wait(lock, [this] { return queue_.size() < capacity_ || !error_.empty(); });
    if (!error_.empty()) throw SinkError(error_);
    if (!spare_.empty()) {
      job.image = std::move(spare_.back());
      spare_.pop_back();
    }
  }
  // Outside the lock: copying 8 MB should not hold up the workers.
  job.image.width = frame.width;
  job.image.height = frame.height;
  job.image.rgba.assign(frame.rgba.begin(), frame.rgba.end());
  job.image.picture = frame.picture;
  {
    const std::lock_guard lock(mutex_);
    queue_.push_back(std::move(job));
  }
  work_ready_.notify_one();
}

void PngSequenceSink::close() {
  stop_workers();
  const std::lock_guard lock(mutex_);
  closed_ = true;
  if (!error_.empty()) throw SinkError(error_);
}

std::size_t PngSequenceSink::frames_written() const {
  const std::lock_guard lock(mutex_);
  return written_;
}

void PngSequenceSink::stop_workers() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& worker : workers_) {
    if (worker.joinable()) worker.join();
  }
  workers_.clear();
}

void PngSequenceSink::work() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      work_ready_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping, and nothing left to write
      job = std::move(queue_.front());
      queue_.pop_front();
      // After a failure the remaining frames are dropped: the run is over.
      if (!error_.empty()) {
        spare_.push_back(std::move(job.image));
        lock.unlock();
        space_ready_.notify_all();
        continue;
      }
    }
    space_ready_.notify_all();
    std::string failure;
    std::string path = pattern_;
    try {
      path = format_frame_path(pattern_, job.index);
      write_png_file(path, job.image, settings_);
    } catch (const SinkError& error) {
      failure = error.what();
    } catch (const std::exception& error) {
      failure = std::string(path).append(": ").append(error.what());
    }
    {
      const std::lock_guard lock(mutex_);
      if (failure.empty()) {
        ++written_;
      } else if (error_.empty()) {
        error_ = std::move(failure);
      }
      spare_.push_back(std::move(job.image));
    }
    // A writer waiting for space must see a failure even when the queue stays full.
    space_ready_.notify_all();
  }
}

}  // namespace rugosim
