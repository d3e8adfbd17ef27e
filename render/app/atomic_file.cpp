#include "render/app/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace rugosim::app {
namespace {

std::runtime_error io_error(const std::string& what, const std::string& path) {
  return std::runtime_error(path + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  // A device or a pipe (/dev/stdout, /dev/full, a FIFO) cannot be replaced by a rename: write
  // to it directly.
  struct stat info {};
  const bool special = ::stat(path_.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
  if (!special) temporary_ = path_ + ".tmp-" + std::to_string(::getpid());
  file_ = std::fopen(special ? path_.c_str() : temporary_.c_str(), "wb");
  if (file_ == nullptr) throw io_error("cannot create", path_);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) {
    std::fclose(file_);
    if (!temporary_.empty()) std::remove(temporary_.c_str());
  }
}

void AtomicFile::write(std::string_view text) {
  if (file_ == nullptr) throw std::runtime_error(path_ + ": write after commit");
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    throw io_error("cannot write", path_);
  }
}

void AtomicFile::commit() {
  if (file_ == nullptr) return;
  const bool flushed =
      std::fflush(file_) == 0 && (temporary_.empty() || ::fsync(::fileno(file_)) == 0);
  const int flush_errno = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    errno = flushed ? errno : flush_errno;
    const std::runtime_error error = io_error("cannot write", path_);
    if (!temporary_.empty()) std::remove(temporary_.c_str());
    throw error;
  }
  if (temporary_.empty()) return;
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const std::runtime_error error = io_error("cannot replace", path_);
    std::remove(temporary_.c_str());
    throw error;
  }
}

RenamedFile::RenamedFile(std::string path)
    : path_(std::move(path)), temporary_(path_ + ".partial-" + std::to_string(::getpid())) {}

RenamedFile::~RenamedFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

void RenamedFile::commit() {
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) throw io_error("rename", path_);
  committed_ = true;
}

void write_text_atomically(const std::string& path, std::string_view text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

std::optional<std::string> read_whole_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(bytes).str();
}

}  // namespace rugosim::app
