#include "render/sinks/gif_sink.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavformat/avio.h>
#include <libavutil/mathematics.h>
#include <libavutil/opt.h>
#include <libavutil/pixfmt.h>
}

#include "render/sinks/libav_support.h"

namespace rugosim {
namespace {

// GIF delays are in centiseconds: the time base of the frames and the packets.
constexpr AVRational kCentiseconds{1, 100};

// One palette for the clip from every pixel of every frame; dithering re-done only inside the
// rectangle a frame changed, so a still background stays still (and compresses).
constexpr const char* kPaletteFilters =
    "split[frames][stats];[stats]palettegen=stats_mode=full[palette];"
    "[frames][palette]paletteuse=dither=sierra2_4a:diff_mode=rectangle";

struct GraphFree {
  void operator()(AVFilterGraph* graph) const { avfilter_graph_free(&graph); }
};
struct InOutFree {
  void operator()(AVFilterInOut* io) const { avfilter_inout_free(&io); }
};

// True when `path` exists and is not a regular file (a device, a pipe): written directly.
bool is_special_file(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode);
}

}  // namespace

bool gif_fps_is_valid(double fps) {
  return std::isfinite(fps) && fps > 0.0 && fps <= 50.0;
}

struct GifSink::Encoder {
  std::string path;     // the target, named by errors
  std::string written;  // the file written: the target, or a temporary beside it
  bool committed = false;
  // Destroyed bottom up: the packet and frames, the filters, the encoder, then the muxer and
  // its file.
  std::unique_ptr<AVFormatContext, FormatContextFree> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  std::unique_ptr<AVFilterGraph, GraphFree> graph;
  std::unique_ptr<AVFrame, FrameFree> filtered;
  std::unique_ptr<AVPacket, PacketFree> packet;
  AVFilterContext* source = nullptr;  // owned by `graph`
  AVFilterContext* sink = nullptr;    // owned by `graph`
  AVStream* stream = nullptr;         // owned by `format`

  ~Encoder() {
    if (!committed && written != path) std::remove(written.c_str());
  }

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw SinkError(
        std::string(path).append(": ").append(what).append(": ").append(av_error_text(code)));
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw SinkError(std::string(path).append(": ").append(what));
  }
  void check(int code, const std::string& what) const {
    if (code < 0) fail(what, code);
  }
  // The AVIO layer keeps a failed write in pb->error rather than returning it.
  void flush_io(const std::string& what) const {
    avio_flush(format->pb);
    if (format->pb->error < 0) fail(what, format->pb->error);
  }

  // Hands `input` (null: end of stream) to the encoder and writes every packet it gives back.
  void encode(const AVFrame* input, const std::string& what) {
    check(avcodec_send_frame(codec.get(), input), what);
    for (;;) {
      const int received = avcodec_receive_packet(codec.get(), packet.get());
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      check(received, what);
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int wrote = av_interleaved_write_frame(format.get(), packet.get());
      av_packet_unref(packet.get());
      check(wrote, "writing a GIF frame");
    }
  }

  // Encodes every frame the palette filters have finished.
  void drain_filters(const std::string& what) {
    for (;;) {
      const int got = av_buffersink_get_frame(sink, filtered.get());
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, what);
      filtered->pict_type = AV_PICTURE_TYPE_NONE;
      encode(filtered.get(), what);
      av_frame_unref(filtered.get());
    }
  }
};

GifSink::GifSink(std::string path, int width, int height, const GifOptions& options)
    : path_(std::move(path)), width_(width), height_(height), fps_(options.fps) {
  if (width < 1 || height < 1 || width > 65535 || height > 65535) {
    throw std::invalid_argument(std::string("a GIF is 1..65535 pixels a side, got ")
                                    .append(std::to_string(width))
                                    .append("x")
                                    .append(std::to_string(height)));
  }
  if (!gif_fps_is_valid(options.fps)) {
    throw std::invalid_argument(
        std::string("a GIF plays at most 50 frames per second (its delays are whole "
                    "centiseconds, and browsers slow delays under 2 cs), got ")
            .append(std::to_string(options.fps)));
  }
  auto encoder = std::make_unique<Encoder>();
  Encoder& e = *encoder;
  e.path = path_;
  e.written = is_special_file(path_)
                  ? path_
                  : std::string(path_).append(".tmp-").append(std::to_string(::getpid()));

  // The palette filters: RGBA frames in, 8-bit palette frames out.
  e.graph.reset(avfilter_graph_alloc());
  if (!e.graph) e.fail("allocating the palette filters", AVERROR(ENOMEM));
  const std::string source_args = std::string("video_size=")
                                      .append(std::to_string(width))
                                      .append("x")
                                      .append(std::to_string(height))
                                      .append(":pix_fmt=rgba:time_base=1/100:pixel_aspect=1/1");
  e.check(avfilter_graph_create_filter(&e.source, avfilter_get_by_name("buffer"), "frames",
                                       source_args.c_str(), nullptr, e.graph.get()),
          "setting up the palette filters' input");
  e.check(avfilter_graph_create_filter(&e.sink, avfilter_get_by_name("buffersink"), "gif", nullptr,
                                       nullptr, e.graph.get()),
          "setting up the palette filters' output");
  const AVPixelFormat palette_only = AV_PIX_FMT_PAL8;
  e.check(av_opt_set_bin(e.sink, "pix_fmts", reinterpret_cast<const std::uint8_t*>(&palette_only),
                         static_cast<int>(sizeof(palette_only)), AV_OPT_SEARCH_CHILDREN),
          "asking the palette filters for 8-bit palette frames");
  std::unique_ptr<AVFilterInOut, InOutFree> into(avfilter_inout_alloc());
  std::unique_ptr<AVFilterInOut, InOutFree> out_of(avfilter_inout_alloc());
  if (!into || !out_of) e.fail("allocating the palette filters", AVERROR(ENOMEM));
  // The graph's open input is fed by the source, its open output feeds the sink.
  out_of->name = av_strdup("in");
  out_of->filter_ctx = e.source;
  into->name = av_strdup("out");
  into->filter_ctx = e.sink;
  AVFilterInOut* inputs = into.release();
  AVFilterInOut* outputs = out_of.release();
  const int parsed =
      avfilter_graph_parse_ptr(e.graph.get(), kPaletteFilters, &inputs, &outputs, nullptr);
  avfilter_inout_free(&inputs);
  avfilter_inout_free(&outputs);
  e.check(parsed, "setting up palettegen and paletteuse");
  e.check(avfilter_graph_config(e.graph.get(), nullptr), "configuring the palette filters");

  // The muxer by name, never from the extension: the path may be a temporary or a pipe.
  AVFormatContext* format = nullptr;
  e.check(avformat_alloc_output_context2(&format, nullptr, "gif", nullptr),
          "setting up the GIF muxer");
  e.format.reset(format);
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_GIF);
  if (codec == nullptr) e.fail("this FFmpeg has no GIF encoder");
  e.stream = avformat_new_stream(format, nullptr);
  if (e.stream == nullptr) e.fail("adding the video stream", AVERROR(ENOMEM));
  e.codec.reset(avcodec_alloc_context3(codec));
  if (!e.codec) e.fail("allocating the GIF encoder", AVERROR(ENOMEM));
  AVCodecContext* c = e.codec.get();
  c->width = width;
  c->height = height;
  c->pix_fmt = AV_PIX_FMT_PAL8;
  c->sample_aspect_ratio = AVRational{1, 1};
  c->time_base = kCentiseconds;
  c->framerate = av_d2q(options.fps, 100000);
  e.check(avcodec_open2(c, codec, nullptr), "opening the GIF encoder");
  e.stream->time_base = kCentiseconds;
  e.stream->avg_frame_rate = c->framerate;
  e.check(avcodec_parameters_from_context(e.stream->codecpar, c),
          "copying the encoder parameters to the stream");
  e.filtered.reset(av_frame_alloc());
  e.packet.reset(av_packet_alloc());
  if (!e.filtered || !e.packet) e.fail("allocating a frame", AVERROR(ENOMEM));

  // "file:" so that the path is always a file system path, never a protocol URL.
  e.check(avio_open2(&format->pb, std::string("file:").append(e.written).c_str(), AVIO_FLAG_WRITE,
                     nullptr, nullptr),
          "opening for writing");
  Dictionary muxer_options;
  e.check(av_dict_set(muxer_options.address(), "loop", "0", 0), "setting the GIF to loop");
  e.check(avformat_write_header(format, muxer_options.address()), "writing the GIF header");
  if (muxer_options.count() != 0) e.fail("the GIF muxer ignored the loop option");
  e.flush_io("writing the GIF header");
  encoder_ = std::move(encoder);
}

GifSink::~GifSink() {
  // Without close() the GIF is incomplete: the temporary file goes, the target stays.
  failed_ = true;
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() is where errors are reported.
  }
}

void GifSink::write(const Image& frame, std::size_t index) {
  const std::string what = std::string("frame ").append(std::to_string(index));
  if (!encoder_) throw SinkError(path_ + ": " + what + " written after the GIF was closed");
  if (frame.width != width_ || frame.height != height_ ||
      frame.rgba.size() != frame.stride() * static_cast<std::size_t>(height_)) {
    failed_ = true;
    throw SinkError(path_ + ": " + what + " is " + std::to_string(frame.width) + "x" +
                    std::to_string(frame.height) + ", the GIF is " + std::to_string(width_) + "x" +
                    std::to_string(height_));
  }
  Encoder& e = *encoder_;
  try {
    std::unique_ptr<AVFrame, FrameFree> input(av_frame_alloc());
    if (!input) e.fail("allocating " + what, AVERROR(ENOMEM));
    input->format = AV_PIX_FMT_RGBA;
    input->width = width_;
    input->height = height_;
    input->sample_aspect_ratio = AVRational{1, 1};
    // Frame k starts at round(100 k / fps) cs: delays of whole centiseconds that keep the
    // clip's length.
    input->pts = std::llround(100.0 * static_cast<double>(frames_written_) / fps_);
    e.check(av_frame_get_buffer(input.get(), 0), "allocating " + what);
    for (int y = 0; y < height_; ++y) {
      std::memcpy(input->data[0] + static_cast<std::ptrdiff_t>(y) * input->linesize[0],
                  frame.pixel(0, y), frame.stride());
    }
    e.check(av_buffersrc_add_frame(e.source, input.get()), "filtering " + what);
    e.drain_filters("encoding " + what);
    ++frames_written_;
  } catch (...) {
    failed_ = true;
    throw;
  }
}

void GifSink::close() {
  if (!encoder_) return;
  // Whatever happens below, the sink is closed afterwards and every libav object is freed
  // (with the temporary file, unless it was put in place).
  const std::unique_ptr<Encoder> encoder = std::move(encoder_);
  Encoder& e = *encoder;
  if (failed_) e.fail("the GIF is incomplete (a frame failed); nothing was written");
  if (frames_written_ == 0) e.fail("no frame to write; nothing was written");
  e.check(av_buffersrc_add_frame(e.source, nullptr), "building the palette");
  e.drain_filters("encoding the frames");
  e.encode(nullptr, "flushing the GIF encoder");
  e.check(av_write_trailer(e.format.get()), "writing the GIF trailer");
  e.flush_io("writing the GIF");
  e.check(avio_closep(&e.format->pb), "closing the file");
  if (e.written != e.path && std::rename(e.written.c_str(), e.path.c_str()) != 0) {
    e.fail(std::string("putting the GIF in place: ").append(std::strerror(errno)));
  }
  e.committed = true;
}

}  // namespace rugosim
