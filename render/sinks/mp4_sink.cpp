#include "render/sinks/mp4_sink.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavformat/avio.h>
#include <libavutil/dict.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/opt.h>
#include <libavutil/pixfmt.h>
#include <libavutil/rational.h>
#include <libswscale/swscale.h>
}

#include "render/sinks/libav_support.h"

namespace rugosim {
namespace {

constexpr std::array<std::string_view, 10> kPresets{"ultrafast", "superfast", "veryfast", "faster",
                                                    "fast",      "medium",    "slow",     "slower",
                                                    "veryslow",  "placebo"};

}  // namespace

void quiet_ffmpeg_logs() {
  av_log_set_level(AV_LOG_ERROR);
}

bool mp4_preset_is_valid(std::string_view preset) {
  return std::find(kPresets.begin(), kPresets.end(), preset) != kPresets.end();
}

bool mp4_crf_is_valid(int crf) {
  return crf >= 0 && crf <= 51;
}

struct Mp4Sink::Encoder : LibavErrors {
  // Destroyed bottom up: the packet and frame, the scaler, the encoder, then the muxer and
  // its file.
  std::unique_ptr<AVFormatContext, FormatContextFree> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  std::unique_ptr<SwsContext, ScalerFree> scaler;
  std::unique_ptr<AVFrame, FrameFree> frame;
  std::unique_ptr<AVPacket, PacketFree> packet;
  AVStream* stream = nullptr;  // owned by `format`
  std::int64_t next_pts = 0;   // in codec time base = frames

  void flush_io(const std::string& what) const { LibavErrors::flush_io(format->pb, what); }

  // Hands `input` (null: end of stream) to the encoder and writes every packet it gives back;
  // each packet that completes a fragment pushes that fragment to the file at once.
  void encode(const AVFrame* input, const std::string& what) {
    check(avcodec_send_frame(codec.get(), input), what);
    for (;;) {
      const int received = avcodec_receive_packet(codec.get(), packet.get());
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      check(received, what);
      // Every frame lasts one tick of the codec time base; libx264 leaves the duration unset,
      // and without it the last sample of a fragment would get a guessed one.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int written = av_interleaved_write_frame(format.get(), packet.get());
      av_packet_unref(packet.get());
      check(written, "writing a packet");
      flush_io("writing a packet");
    }
  }
};

Mp4Sink::Mp4Sink(std::string path, int width, int height, const Mp4Options& options)
    : path_(std::move(path)), width_(width), height_(height), keyframe_interval_(0) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
    throw std::invalid_argument(std::string("MP4 needs an even width and height, got ")
                                    .append(std::to_string(width))
                                    .append("x")
                                    .append(std::to_string(height)));
  }
  if (!std::isfinite(options.fps) || options.fps <= 0) {
    throw std::invalid_argument(
        std::string("MP4 frame rate must be a positive number of frames per second, got ")
            .append(std::to_string(options.fps)));
  }
  if (!mp4_crf_is_valid(options.crf)) {
    throw std::invalid_argument(
        std::string("MP4 crf must be in 0..51, got ").append(std::to_string(options.crf)));
  }
  if (!mp4_preset_is_valid(options.preset)) {
    throw std::invalid_argument(
        std::string("unknown x264 preset \"")
            .append(options.preset)
            .append("\" (expected ultrafast, superfast, veryfast, faster, fast, medium, slow, "
                    "slower, veryslow or placebo)"));
  }
  if (options.keyframe_interval < 0) {
    throw std::invalid_argument(std::string("MP4 keyframe interval must be >= 0 frames, got ")
                                    .append(std::to_string(options.keyframe_interval)));
  }
  if (options.threads < 0) {
    throw std::invalid_argument(std::string("MP4 encoder threads must be >= 0, got ")
                                    .append(std::to_string(options.threads)));
  }
  const AVRational frame_rate = av_d2q(options.fps, 100000);
  if (frame_rate.num <= 0 || frame_rate.den <= 0) {
    throw std::invalid_argument(
        std::string("MP4 frame rate out of range: ").append(std::to_string(options.fps)));
  }
  keyframe_interval_ =
      options.keyframe_interval > 0
          ? options.keyframe_interval
          : std::max(1, static_cast<int>(std::min(std::lround(options.fps), long{1} << 20)));

  auto encoder = std::make_unique<Encoder>();
  Encoder& e = *encoder;
  e.path = path_;

  // The muxer by name, never from the extension: the path may be /dev/full or a pipe.
  AVFormatContext* format = nullptr;
  e.check(avformat_alloc_output_context2(&format, nullptr, "mp4", nullptr),
          "setting up the MP4 muxer");
  e.format.reset(format);

  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  if (codec == nullptr) e.fail("this FFmpeg has no libx264 encoder");
  e.stream = avformat_new_stream(format, nullptr);
  if (e.stream == nullptr) e.fail("adding the video stream", AVERROR(ENOMEM));
  e.codec.reset(avcodec_alloc_context3(codec));
  if (!e.codec) e.fail("allocating the H.264 encoder", AVERROR(ENOMEM));

  AVCodecContext* c = e.codec.get();
  c->width = width;
  c->height = height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->sample_aspect_ratio = AVRational{1, 1};
  c->framerate = frame_rate;
  c->time_base = av_inv_q(frame_rate);  // one tick per frame
  c->gop_size = keyframe_interval_;     // x264's keyint: the longest fragment, in frames
  c->thread_count = options.threads;    // 0: x264's automatic count
  // BT.709 in limited range, stated in the stream and matched by the conversion below.
  c->color_range = AVCOL_RANGE_MPEG;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->colorspace = AVCOL_SPC_BT709;
  c->chroma_sample_location = AVCHROMA_LOC_LEFT;
  if ((format->oformat->flags & AVFMT_GLOBALHEADER) != 0) {
    c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  }
  e.check(av_opt_set(c->priv_data, "preset", options.preset.c_str(), 0), "setting the x264 preset");
  e.check(av_opt_set_double(c->priv_data, "crf", options.crf, 0), "setting the x264 crf");
  if (options.stitchable) {
    e.check(av_opt_set(c->priv_data, "x264-params", "stitchable=1", 0),
            "setting x264's stitchable");
  }
  e.check(avcodec_open2(c, codec, nullptr), "opening the libx264 encoder");

  e.stream->time_base = c->time_base;  // a hint: the muxer picks its own in write_header
  e.stream->avg_frame_rate = frame_rate;
  e.check(avcodec_parameters_from_context(e.stream->codecpar, c),
          "copying the encoder parameters to the stream");

  e.frame.reset(av_frame_alloc());
  e.packet.reset(av_packet_alloc());
  if (!e.frame || !e.packet) e.fail("allocating a frame", AVERROR(ENOMEM));
  e.frame->format = c->pix_fmt;
  e.frame->width = width;
  e.frame->height = height;
  e.frame->color_range = c->color_range;
  e.frame->color_primaries = c->color_primaries;
  e.frame->color_trc = c->color_trc;
  e.frame->colorspace = c->colorspace;
  e.check(av_frame_get_buffer(e.frame.get(), 0), "allocating a frame");

  e.scaler.reset(sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                                SWS_BICUBIC, nullptr, nullptr, nullptr));
  if (!e.scaler) e.fail("libswscale cannot convert RGBA to yuv420p");
  // Full-range RGB in, BT.709 limited-range YUV out: the same matrix as the stream's tags, so
  // a player turns the YUV back into the rendered colours.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  if (sws_setColorspaceDetails(e.scaler.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16) < 0) {
    e.fail("libswscale cannot convert to BT.709 YUV");
  }

  // "file:" so that the path is always a file system path, never a protocol URL.
  e.check(avio_open2(&format->pb, std::string("file:").append(path_).c_str(), AVIO_FLAG_WRITE,
                     nullptr, nullptr),
          "opening for writing");
  Dictionary muxer_options;
  e.check(av_dict_set(muxer_options.address(), "movflags", kFragmentedMovFlags, 0),
          "setting the MP4 flags");
  if (!options.comment.empty()) {
    e.check(av_dict_set(&format->metadata, "comment", options.comment.c_str(), 0),
            "setting the MP4 comment");
  }
  e.check(avformat_write_header(format, muxer_options.address()), "writing the MP4 header");
  if (muxer_options.count() != 0) e.fail("the MP4 muxer ignored the fragmentation flags");
  // The header is small and would sit in the AVIO buffer; pushing it now makes a full disk or
  // an unwritable device fail here rather than after the first frames were rendered.
  e.flush_io("writing the MP4 header");

  encoder_ = std::move(encoder);
}

Mp4Sink::~Mp4Sink() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() is where errors are reported.
  }
}

void Mp4Sink::write(const Image& frame, std::size_t index) {
  if (!encoder_) {
    throw SinkError(std::string(path_)
                        .append(": frame ")
                        .append(std::to_string(index))
                        .append(" written after the MP4 was closed"));
  }
  if (frame.width != width_ || frame.height != height_ ||
      frame.rgba.size() != frame.stride() * static_cast<std::size_t>(height_)) {
    throw SinkError(std::string(path_)
                        .append(": frame ")
                        .append(std::to_string(index))
                        .append(" is ")
                        .append(std::to_string(frame.width))
                        .append("x")
                        .append(std::to_string(frame.height))
                        .append(" (")
                        .append(std::to_string(frame.rgba.size()))
                        .append(" bytes), the MP4 is ")
                        .append(std::to_string(width_))
                        .append("x")
                        .append(std::to_string(height_)));
  }
  Encoder& e = *encoder_;
  const std::string what = std::string("encoding frame ").append(std::to_string(index));
  // The encoder may still hold a reference to the previous frame's buffers (then this copies
  // them: what they hold stays).
  e.check(av_frame_make_writable(e.frame.get()), what);
  // The picture converted last time again (a scene at rest): its YUV is still in the frame.
  if (frame.picture == 0 || frame.picture != converted_picture_) {
    converted_picture_ = 0;
    const std::uint8_t* const source[] = {frame.rgba.data()};
    const int source_stride[] = {static_cast<int>(frame.stride())};
    const int rows = sws_scale(e.scaler.get(), source, source_stride, 0, height_, e.frame->data,
                               e.frame->linesize);
    if (rows < 0) e.fail(std::string("converting frame ").append(std::to_string(index)), rows);
    converted_picture_ = frame.picture;
  }
  // Consecutive timestamps whatever the index: the clip has no gaps, and lasts frames / fps.
  e.frame->pts = e.next_pts++;
  ++frames_written_;
  e.encode(e.frame.get(), what);
}

void Mp4Sink::close() {
  if (!encoder_) return;
  // Whatever happens below, the sink is closed afterwards and every libav object is freed.
  const std::unique_ptr<Encoder> encoder = std::move(encoder_);
  Encoder& e = *encoder;
  e.encode(nullptr, "flushing the encoder");
  e.check(av_write_trailer(e.format.get()), "writing the MP4 trailer");
  e.flush_io("writing the MP4 trailer");
  e.check(avio_closep(&e.format->pb), "closing the file");
}

}  // namespace rugosim
