// Output files written whole or not at all: the app's text outputs (AtomicFile) and files that an
// encoder fills under a temporary name (RenamedFile).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "render/sinks/atomic_output_file.h"

namespace rugosim::app {

// The app's text outputs (CSV, stats, checkpoints, sweep files) are written like the sinks'
// frames, through the render library's AtomicOutputFile (render/sinks/atomic_output_file.h):
// whole or not at all, flushed to disk before they replace the target.
using AtomicFile = AtomicOutputFile;

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

// `text` written to `path` through an AtomicFile: whole or not at all. Throws SinkError
// (a std::runtime_error) naming the path.
void write_text_atomically(const std::string& path, std::string_view text);

// Every byte of the file at `path`; nullopt when it is missing, a folder or cannot be read.
std::optional<std::string> read_whole_file(const std::string& path);

}  // namespace rugosim::app
