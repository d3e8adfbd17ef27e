#include "support/webp_probe.h"

#include <cstring>
#include <memory>
#include <stdexcept>
#include <webp/demux.h>

#include "support/file_text.h"

namespace rugosim::testing {
namespace {

struct DecoderFree {
  void operator()(WebPAnimDecoder* decoder) const { WebPAnimDecoderDelete(decoder); }
};

}  // namespace

WebpProbe probe_webp(const std::string& path) {
  const std::string bytes = read_text(path);
  if (bytes.empty()) throw std::runtime_error(path + ": cannot read it, or it is empty");
  WebPData data;
  data.bytes = reinterpret_cast<const std::uint8_t*>(bytes.data());
  data.size = bytes.size();
  WebPAnimDecoderOptions options;
  if (!WebPAnimDecoderOptionsInit(&options)) throw std::runtime_error("libwebp version mismatch");
  options.color_mode = MODE_RGBA;  // straight alpha
  options.use_threads = 0;
  const std::unique_ptr<WebPAnimDecoder, DecoderFree> decoder(WebPAnimDecoderNew(&data, &options));
  if (!decoder) throw std::runtime_error(path + ": not an animated WebP libwebp can decode");
  WebPAnimInfo info;
  if (!WebPAnimDecoderGetInfo(decoder.get(), &info)) {
    throw std::runtime_error(path + ": no animation information");
  }
  WebpProbe probe;
  probe.width = static_cast<int>(info.canvas_width);
  probe.height = static_cast<int>(info.canvas_height);
  probe.loop_count = static_cast<int>(info.loop_count);
  while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
    std::uint8_t* pixels = nullptr;
    int timestamp = 0;
    if (!WebPAnimDecoderGetNext(decoder.get(), &pixels, &timestamp)) {
      throw std::runtime_error(path + ": a frame does not decode");
    }
    Image frame(probe.width, probe.height);
    std::memcpy(frame.rgba.data(), pixels, frame.rgba.size());
    probe.frames.push_back(std::move(frame));
    probe.timestamps.push_back(timestamp);
  }
  return probe;
}

}  // namespace rugosim::testing
