#include "render/sinks/libav_support.h"

#include <array>
#include <cstdio>

extern "C" {
#include <libavutil/error.h>
}

namespace rugosim {

std::string av_error_text(int code) {
  std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
  if (av_strerror(code, text.data(), text.size()) < 0) {
    std::snprintf(text.data(), text.size(), "error %d", code);
  }
  return std::string(text.data());
}

void LibavErrors::fail(const std::string& what, int code) const {
  throw SinkError(path + ": " + what + ": " + av_error_text(code));
}

void LibavErrors::fail(const std::string& what) const {
  throw SinkError(path + ": " + what);
}

void LibavErrors::flush_io(AVIOContext* pb, const std::string& what) const {
  if (pb == nullptr) return;
  avio_flush(pb);
  if (pb->error < 0) fail(what, pb->error);
}

}  // namespace rugosim
