// An output file written whole or not at all, for every file the program writes itself: frames
// and stills (PNG, SVG, PDF) and the app's text outputs (CSV, stats, checkpoints, sweep tables).
//
// The bytes go to a temporary file beside the target ("<target>.tmp-<pid>-<n>"), which replaces
// the target only on commit(); a run that fails or is abandoned leaves the target as it was and
// removes the temporary file. A target that is a symbolic link keeps its link: the file it
// points to is the one replaced. A target that exists and is not a regular file (a device, a
// FIFO, /dev/stdout) cannot be replaced by a rename, so it is written directly.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace rugosim {

class AtomicOutputFile {
 public:
  // Whether commit() waits for the bytes to reach the disk before the rename: what a run keeps
  // (statistics, checkpoints, tables) survives a power loss whole; frames of a sequence are
  // only renamed (each is cheap to draw again, and a flush per frame costs about 0.8 ms of a
  // few milliseconds on this project's machines).
  enum class Flush { kToDisk, kRenameOnly };

  // Creates the temporary file; throws SinkError (frame_sink.h) naming `path` and the system's
  // reason when it cannot.
  explicit AtomicOutputFile(std::string path, Flush flush = Flush::kToDisk);
  ~AtomicOutputFile();  // without commit(): the temporary file goes, the target stays
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  // Appends; throws SinkError on a write error (a full disk, a file size limit).
  void write(std::span<const std::uint8_t> bytes);
  void write(std::string_view text);
  // Closes and renames over the target; throws SinkError on failure (the target stays as it
  // was). A second call does nothing.
  void commit();

  const std::string& path() const { return path_; }

 private:
  std::string path_;       // as given: what errors name
  std::string target_;     // the file replaced: path_, or the file its link points to
  std::string temporary_;  // empty when the target is written directly
  Flush flush_;
  int fd_ = -1;
};

// `bytes` written to `path` through an AtomicOutputFile, whole or not at all.
void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes,
                           AtomicOutputFile::Flush flush = AtomicOutputFile::Flush::kToDisk);

}  // namespace rugosim
