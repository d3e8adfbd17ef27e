// An output file written atomically: the text goes to a temporary file beside the target,
// which replaces the target only on commit(). A run that fails or is abandoned leaves the
// target as it was (no partial or truncated output) and removes the temporary file. A target
// that exists and is not a regular file (a device, a pipe) is written directly.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace rugosim::app {

class AtomicFile {
 public:
  // Opens "<path>.tmp-<pid>" for writing; throws std::runtime_error naming the path and the
  // system's reason when it cannot.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends text; throws std::runtime_error on a write error (e.g. a full disk).
  void write(std::string_view text);
  // Flushes, closes and renames over the target; throws std::runtime_error on failure.
  void commit();

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporary_;
  std::FILE* file_ = nullptr;
};

// A file that another writer (an encoder) fills under a temporary name beside `path`, renamed
// to `path` on commit(); without commit (an error, an interruption) the temporary file is
// removed. So a file at `path` is always complete.
class RenamedFile {
 public:
  explicit RenamedFile(std::string path);
  ~RenamedFile();
  RenamedFile(const RenamedFile&) = delete;
  RenamedFile& operator=(const RenamedFile&) = delete;

  const std::string& temporary() const { return temporary_; }
  // Renames the temporary file over `path`; throws std::runtime_error on failure.
  void commit();

 private:
  std::string path_;
  std::string temporary_;
  bool committed_ = false;
};

// `text` written to `path` through an AtomicFile: whole or not at all. Throws as AtomicFile does.
// (Binary files of the sinks: png_io.h's write_file_atomically.)
void write_text_atomically(const std::string& path, std::string_view text);

// Every byte of the file at `path`; nullopt when it is missing, a folder or cannot be read.
std::optional<std::string> read_whole_file(const std::string& path);

}  // namespace rugosim::app
