#include "support/video_probe.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/pixfmt.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

#include "render/sinks/libav_support.h"

namespace rugosim::testing {
namespace {

struct InputFree {
  void operator()(AVFormatContext* input) const { avformat_close_input(&input); }
};

class Prober {
 public:
  Prober(const std::string& path, bool decode_pixels, FileEnd end)
      : path_(path), decode_pixels_(decode_pixels), end_(end) {}

  VideoProbe run() {
    AVFormatContext* input = nullptr;
    check(avformat_open_input(&input, std::string("file:").append(path_).c_str(), nullptr, nullptr),
          "opening");
    input_.reset(input);
    check(avformat_find_stream_info(input, nullptr), "reading the stream information");
    const int stream_index = av_find_best_stream(input, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    check(stream_index, "finding a video stream");
    const AVStream* stream = input->streams[stream_index];
    // VP9's alpha travels beside the colour, and FFmpeg's own VP9 decoder drops it: libvpx's
    // keeps it.
    const AVCodec* decoder = stream->codecpar->codec_id == AV_CODEC_ID_VP9
                                 ? avcodec_find_decoder_by_name("libvpx-vp9")
                                 : avcodec_find_decoder(stream->codecpar->codec_id);
    if (decoder == nullptr) fail("no decoder for its video");
    codec_.reset(avcodec_alloc_context3(decoder));
    frame_.reset(av_frame_alloc());
    AVPacket* packet = av_packet_alloc();
    std::unique_ptr<AVPacket, PacketFree> packet_owner(packet);
    if (!codec_ || !frame_ || !packet) fail("out of memory");
    check(avcodec_parameters_to_context(codec_.get(), stream->codecpar), "setting up the decoder");
    codec_->thread_count = 1;
    check(avcodec_open2(codec_.get(), decoder, nullptr), "opening the decoder");

    VideoProbe probe;
    probe.codec = avcodec_get_name(stream->codecpar->codec_id);
    probe.width = stream->codecpar->width;
    probe.height = stream->codecpar->height;
    AVRational rate = stream->avg_frame_rate;
    if (rate.num <= 0 || rate.den <= 0) rate = stream->r_frame_rate;
    if (rate.num > 0 && rate.den > 0) probe.fps = av_q2d(rate);

    // Duration from the packets' timestamps, in the stream's time base.
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    std::int64_t end = std::numeric_limits<std::int64_t>::min();
    const std::int64_t frame_ticks =
        probe.fps > 0 ? av_rescale_q(1, av_inv_q(rate), stream->time_base) : 0;
    const std::int64_t file_bytes = avio_size(input->pb);
    for (;;) {
      const int read = av_read_frame(input, packet);
      if (read == AVERROR_EOF) break;
      if (read < 0 && end_ == FileEnd::may_be_cut && avio_feof(input->pb)) {
        break;  // the demuxer ran into the end inside a fragment's header
      }
      check(read, "reading a packet");
      // A sample the file ends inside comes back short and flagged corrupt: it is the cut
      // tail, and nothing follows it.
      if (end_ == FileEnd::may_be_cut && (packet->flags & AV_PKT_FLAG_CORRUPT) != 0 &&
          file_bytes > 0 && packet->pos >= 0 && packet->pos + packet->size >= file_bytes) {
        av_packet_unref(packet);
        break;
      }
      if (packet->stream_index == stream_index) {
        if (packet->pts != AV_NOPTS_VALUE) {
          first = std::min(first, packet->pts);
          end =
              std::max(end, packet->pts + (packet->duration > 0 ? packet->duration : frame_ticks));
        }
        const int sent = avcodec_send_packet(codec_.get(), packet);
        av_packet_unref(packet);
        check(sent, "decoding");
        receive_frames(probe);
      } else {
        av_packet_unref(packet);
      }
    }
    check(avcodec_send_packet(codec_.get(), nullptr), "draining the decoder");
    receive_frames(probe);

    if (end > first) {
      probe.duration_s = static_cast<double>(end - first) * av_q2d(stream->time_base);
    } else if (probe.fps > 0) {
      probe.duration_s = static_cast<double>(probe.frames) / probe.fps;
    }
    return probe;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(std::string(path_).append(": ").append(what));
  }
  void check(int code, const std::string& what) const {
    if (code < 0) fail(std::string(what).append(": ").append(av_error_text(code)));
  }

  void receive_frames(VideoProbe& probe) {
    for (;;) {
      const int received = avcodec_receive_frame(codec_.get(), frame_.get());
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      check(received, "decoding");
      ++probe.frames;
      if (decode_pixels_) probe.decoded_rgba.push_back(to_rgba(*frame_));
      av_frame_unref(frame_.get());
    }
  }

  Image to_rgba(const AVFrame& frame) {
    const auto format = static_cast<AVPixelFormat>(frame.format);
    scaler_.reset(sws_getCachedContext(scaler_.release(), frame.width, frame.height, format,
                                       frame.width, frame.height, AV_PIX_FMT_RGBA,
                                       SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT,
                                       nullptr, nullptr, nullptr));
    if (!scaler_) fail("libswscale cannot convert the decoded frames to RGBA");
    const int matrix =
        frame.colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;  // BT.601
    const int* coefficients = sws_getCoefficients(matrix);
    const int full_range = frame.color_range == AVCOL_RANGE_JPEG ? 1 : 0;
    if (sws_setColorspaceDetails(scaler_.get(), coefficients, full_range, coefficients, 1, 0,
                                 1 << 16, 1 << 16) < 0) {
      fail("libswscale cannot convert from the stream's colour space");
    }
    Image image(frame.width, frame.height);
    std::uint8_t* const destination[] = {image.rgba.data()};
    const int destination_stride[] = {static_cast<int>(image.stride())};
    const int rows = sws_scale(scaler_.get(), frame.data, frame.linesize, 0, frame.height,
                               destination, destination_stride);
    if (rows != frame.height) fail("converting a decoded frame to RGBA");
    return image;
  }

  std::string path_;
  bool decode_pixels_;
  FileEnd end_;
  // The decoder and frames go before the input they read from.
  std::unique_ptr<AVFormatContext, InputFree> input_;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec_;
  std::unique_ptr<AVFrame, FrameFree> frame_;
  std::unique_ptr<SwsContext, ScalerFree> scaler_;
};

}  // namespace

VideoProbe probe_video(const std::string& path, bool decode_pixels, FileEnd end) {
  return Prober(path, decode_pixels, end).run();
}

}  // namespace rugosim::testing
