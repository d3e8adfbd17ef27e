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

}  // namespace rugosim
