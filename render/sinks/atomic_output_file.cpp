#include "render/sinks/atomic_output_file.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

#include "render/sinks/frame_sink.h"

namespace rugosim {
namespace {

SinkError file_error(const std::string& path, const char* what, int error_number) {
  return SinkError(
      std::string(path).append(": ").append(what).append(": ").append(std::strerror(error_number)));
}

// The file a rename must replace: `path` itself (new, or a regular file), the file its link
// points to, or "" when it exists and is not a regular file (written directly).
std::string replace_target(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return path;  // a new file (or an error on create)
  if (!S_ISREG(status.st_mode) || path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0) {
    return {};
  }
  struct stat link_status {};
  if (::lstat(path.c_str(), &link_status) != 0 || !S_ISLNK(link_status.st_mode)) return path;
  const std::unique_ptr<char, decltype(&std::free)> resolved(::realpath(path.c_str(), nullptr),
                                                             &std::free);
  if (resolved == nullptr) throw file_error(path, "cannot resolve the link", errno);
  return std::string(resolved.get());
}

// Unique within the process too: the PNG sequence writes several frames at once.
std::string temporary_name(const std::string& target) {
  static std::atomic<unsigned long> counter{0};
  return std::string(target)
      .append(".tmp-")
      .append(std::to_string(::getpid()))
      .append("-")
      .append(std::to_string(counter.fetch_add(1)));
}

}  // namespace

AtomicOutputFile::AtomicOutputFile(std::string path, Flush flush)
    : path_(std::move(path)), target_(replace_target(path_)), flush_(flush) {
  if (target_.empty()) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) throw file_error(path_, "cannot open", errno);
    return;
  }
  temporary_ = temporary_name(target_);
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) throw file_error(path_, "cannot create", errno);
}

AtomicOutputFile::~AtomicOutputFile() {
  if (fd_ < 0) return;
  ::close(fd_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicOutputFile::write(std::span<const std::uint8_t> bytes) {
  if (fd_ < 0) throw SinkError(path_ + ": written after it was committed");
  const std::uint8_t* data = bytes.data();
  std::size_t size = bytes.size();
  while (size > 0) {
    const ssize_t written = ::write(fd_, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw file_error(path_, "cannot write", errno);
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
}

void AtomicOutputFile::write(std::string_view text) {
  write(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void AtomicOutputFile::commit() {
  if (fd_ < 0) return;
  const int fd = std::exchange(fd_, -1);
  const bool synced = temporary_.empty() || flush_ == Flush::kRenameOnly || ::fsync(fd) == 0;
  int error_number = errno;
  const bool closed = ::close(fd) == 0;
  if (synced && !closed) error_number = errno;
  if (!synced || !closed) {
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
    throw file_error(path_, "cannot write", error_number);
  }
  if (temporary_.empty()) return;
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    error_number = errno;
    ::unlink(temporary_.c_str());
    throw file_error(path_, "cannot replace", error_number);
  }
}

void write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes,
                           AtomicOutputFile::Flush flush) {
  AtomicOutputFile file(path, flush);
  file.write(bytes);
  file.commit();
}

}  // namespace rugosim
