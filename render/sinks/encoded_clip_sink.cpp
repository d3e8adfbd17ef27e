#include "render/sinks/encoded_clip_sink.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <thread>
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

#include "render/bounded_queue.h"
#include "render/first_error.h"
#include "render/sinks/libav_support.h"

namespace rugosim {
namespace {

// What one format needs of FFmpeg.
struct FormatSpec {
  const char* muxer;
  const char* encoder;
  AVPixelFormat pixels;  // the encoder's input
  const char* filters;   // RGBA (or, opaque, RGB) in, `pixels` out
  bool yuv;              // tagged BT.709, limited range
};

// GIF: one palette for the clip from every pixel of every frame; dithering redone only inside
// the rectangle a frame changed, so a still background stays still (and compresses); a pixel
// under half opaque takes the transparent entry.
constexpr const char* kGifFilters =
    "split[frames][stats];[stats]palettegen=stats_mode=full:reserve_transparent=1[palette];"
    "[frames][palette]paletteuse=dither=sierra2_4a:diff_mode=rectangle:alpha_threshold=128";

FormatSpec spec_of(ClipFormat format, bool alpha) {
  switch (format) {
    case ClipFormat::kGif:
      return {"gif", "gif", AV_PIX_FMT_PAL8, kGifFilters, false};
    case ClipFormat::kWebm:
      return {"webm", "libvpx-vp9", alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P,
              alpha ? "scale=out_color_matrix=bt709:out_range=tv,format=yuva420p"
                    : "scale=out_color_matrix=bt709:out_range=tv,format=yuv420p",
              true};
    case ClipFormat::kMov:
      return {"mov", "prores_ks", alpha ? AV_PIX_FMT_YUVA444P10LE : AV_PIX_FMT_YUV444P10LE,
              alpha ? "scale=out_color_matrix=bt709:out_range=tv,format=yuva444p10le"
                    : "scale=out_color_matrix=bt709:out_range=tv,format=yuv444p10le",
              true};
    case ClipFormat::kWebp:
      return {"webp", "libwebp_anim", AV_PIX_FMT_BGRA, "format=bgra", false};
  }
  return {};
}

// The time base of frames and packets: GIF counts centiseconds, WebP milliseconds (frame k
// at round(k/fps) in those units); the video formats count frames.
AVRational time_base_of(ClipFormat format, double fps) {
  if (format == ClipFormat::kGif) return {1, 100};
  if (format == ClipFormat::kWebp) return {1, 1000};
  return av_inv_q(av_d2q(fps, 100000));
}

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

std::optional<ClipFormat> parse_clip_format(std::string_view name) {
  for (const ClipFormat f :
       {ClipFormat::kGif, ClipFormat::kWebm, ClipFormat::kMov, ClipFormat::kWebp}) {
    if (clip_format_name(f) == name) return f;
  }
  return std::nullopt;
}

std::string_view clip_format_name(ClipFormat format) {
  switch (format) {
    case ClipFormat::kGif:
      return "gif";
    case ClipFormat::kWebm:
      return "webm";
    case ClipFormat::kMov:
      return "mov";
    case ClipFormat::kWebp:
      return "webp";
  }
  return "";
}

bool clip_fps_is_valid(ClipFormat format, double fps) {
  const double most = format == ClipFormat::kGif ? 50.0 : 1000.0;
  return std::isfinite(fps) && fps > 0.0 && fps <= most;
}

// The filters run on the thread that writes the frames, the encoder and the muxer on a thread of
// their own, fed the filtered frames through a short queue: filtering frame k + 1 (for WebM the
// colour conversion and a copy, a tenth of the clip's CPU time) overlaps encoding frame k, which
// leaves cores idle between its rows. The frames reach the encoder in order, so the clip is
// the same bytes as when encoded on one thread.
struct EncodedClipSink::Encoder : LibavErrors {  // path: the target, named by errors
  using FramePtr = std::unique_ptr<AVFrame, FrameFree>;
  // Filtered frames waiting for the encoder: two keep it busy while the filters make the next.
  static constexpr std::size_t kFramesQueued = 2;

  std::string written;  // the file written: the target, or a temporary beside it
  bool committed = false;
  // Destroyed bottom up: the queue, the packet and frames, the filters, the encoder, then the
  // muxer and its file (the encoding thread has stopped by then: ~Encoder).
  std::unique_ptr<AVFormatContext, FormatContextFree> format;
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  std::unique_ptr<AVFilterGraph, GraphFree> graph;
  FramePtr filtered;
  std::unique_ptr<AVPacket, PacketFree> packet;
  AVFilterContext* source = nullptr;  // owned by `graph`
  AVFilterContext* sink = nullptr;    // owned by `graph`
  AVStream* stream = nullptr;         // owned by `format`
  BoundedQueue<FramePtr> to_encode{kFramesQueued};
  std::thread encoding;       // runs encode_queued() from start_encoding() until stop_encoding()
  FirstError encoding_error;  // the encoding thread's failure, rethrown by the writer

  ~Encoder() {
    stop_encoding();
    if (!committed && written != path) std::remove(written.c_str());
  }

  void flush_io(const std::string& what) const { LibavErrors::flush_io(format->pb, what); }

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
      check(wrote, "writing a packet");
    }
  }

  void start_encoding() {
    encoding = std::thread([this] { encode_queued(); });
  }

  // The encoding thread: every queued frame, in order, until the queue closes. A failure stops
  // it and closes the queue, so that a writer waiting for room wakes and reports it.
  void encode_queued() {
    std::size_t frame = 0;
    try {
      while (std::optional<FramePtr> next = to_encode.pop()) {
        encode(next->get(), std::string("encoding frame ").append(std::to_string(frame++)));
      }
    } catch (...) {
      encoding_error.capture();
      to_encode.close();
    }
  }

  // Waits for the encoding thread to finish what was queued; then rethrows its failure, if any.
  void stop_encoding() {
    to_encode.close();
    if (encoding.joinable()) encoding.join();
  }

  // Queues every frame the filters have finished for the encoder.
  void drain_filters(const std::string& what) {
    for (;;) {
      const int got = av_buffersink_get_frame(sink, filtered.get());
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      check(got, what);
      filtered->pict_type = AV_PICTURE_TYPE_NONE;
      // The colour the filters made, stated on the frame too: ProRes writes the frame's tags.
      if (codec->colorspace != AVCOL_SPC_UNSPECIFIED) {
        filtered->color_range = codec->color_range;
        filtered->color_primaries = codec->color_primaries;
        filtered->color_trc = codec->color_trc;
        filtered->colorspace = codec->colorspace;
      }
      FramePtr queued(av_frame_alloc());
      if (!queued) fail(what, AVERROR(ENOMEM));
      av_frame_move_ref(queued.get(), filtered.get());  // the pixels, not a copy
      if (!to_encode.push(std::move(queued))) {
        encoding_error.rethrow();  // the encoder stopped on a failure
        fail(what + ": the encoder has stopped");
      }
    }
  }
};

EncodedClipSink::EncodedClipSink(std::string path, ClipFormat format, int width, int height,
                                 const ClipOptions& options)
    : path_(std::move(path)), format_(format), width_(width), height_(height), fps_(options.fps) {
  const std::string name(clip_format_name(format));
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    throw std::invalid_argument(name + " frames are 1..16384 pixels a side, got " +
                                std::to_string(width) + "x" + std::to_string(height));
  }
  if (!clip_fps_is_valid(format, options.fps)) {
    throw std::invalid_argument(
        format == ClipFormat::kGif
            ? "a GIF plays at most 50 frames per second (its delays are whole centiseconds, and "
              "browsers slow delays under 2 cs), got " +
                  std::to_string(options.fps)
            : "frames per second must be in (0, 1000], got " + std::to_string(options.fps));
  }
  const FormatSpec spec = spec_of(format, options.alpha);
  const AVRational time_base = time_base_of(format, options.fps);
  auto encoder = std::make_unique<Encoder>();
  Encoder& e = *encoder;
  e.path = path_;
  e.written = is_special_file(path_)
                  ? path_
                  : std::string(path_).append(".tmp-").append(std::to_string(::getpid()));

  // The filters: RGBA frames in (RGB when opaque: alpha dropped), the encoder's pixels out.
  e.graph.reset(avfilter_graph_alloc());
  if (!e.graph) e.fail("allocating the filters", AVERROR(ENOMEM));
  const std::string source_args = "video_size=" + std::to_string(width) + "x" +
                                  std::to_string(height) +
                                  ":pix_fmt=rgba:time_base=" + std::to_string(time_base.num) + "/" +
                                  std::to_string(time_base.den) + ":pixel_aspect=1/1";
  e.check(avfilter_graph_create_filter(&e.source, avfilter_get_by_name("buffer"), "frames",
                                       source_args.c_str(), nullptr, e.graph.get()),
          "setting up the filters' input");
  e.check(avfilter_graph_create_filter(&e.sink, avfilter_get_by_name("buffersink"), "encoder",
                                       nullptr, nullptr, e.graph.get()),
          "setting up the filters' output");
  e.check(av_opt_set_bin(e.sink, "pix_fmts", reinterpret_cast<const std::uint8_t*>(&spec.pixels),
                         static_cast<int>(sizeof(spec.pixels)), AV_OPT_SEARCH_CHILDREN),
          "asking the filters for the encoder's pixels");
  std::unique_ptr<AVFilterInOut, InOutFree> into(avfilter_inout_alloc());
  std::unique_ptr<AVFilterInOut, InOutFree> out_of(avfilter_inout_alloc());
  if (!into || !out_of) e.fail("allocating the filters", AVERROR(ENOMEM));
  // The graph's open input is fed by the source, its open output feeds the sink.
  out_of->name = av_strdup("in");
  out_of->filter_ctx = e.source;
  into->name = av_strdup("out");
  into->filter_ctx = e.sink;
  if (out_of->name == nullptr || into->name == nullptr) {
    e.fail("allocating the filters", AVERROR(ENOMEM));
  }
  AVFilterInOut* inputs = into.release();
  AVFilterInOut* outputs = out_of.release();
  const std::string filters = (options.alpha ? "" : "format=rgb24,") + std::string(spec.filters);
  const int parsed =
      avfilter_graph_parse_ptr(e.graph.get(), filters.c_str(), &inputs, &outputs, nullptr);
  avfilter_inout_free(&inputs);
  avfilter_inout_free(&outputs);
  e.check(parsed, "setting up the filters " + filters);
  e.check(avfilter_graph_config(e.graph.get(), nullptr), "configuring the filters");

  // The muxer by name, never from the extension: the path may be a temporary or a pipe.
  AVFormatContext* muxer = nullptr;
  e.check(avformat_alloc_output_context2(&muxer, nullptr, spec.muxer, nullptr),
          "setting up the " + name + " muxer");
  e.format.reset(muxer);
  // The same frames make the same file: the Matroska muxer otherwise writes a random segment
  // UID (which WebM does not use) and its library version.
  if (format == ClipFormat::kWebm) muxer->flags |= AVFMT_FLAG_BITEXACT;
  const AVCodec* codec = avcodec_find_encoder_by_name(spec.encoder);
  if (codec == nullptr) e.fail(std::string("this FFmpeg has no ") + spec.encoder + " encoder");
  e.stream = avformat_new_stream(muxer, nullptr);
  if (e.stream == nullptr) e.fail("adding the video stream", AVERROR(ENOMEM));
  e.codec.reset(avcodec_alloc_context3(codec));
  if (!e.codec) e.fail(std::string("allocating the ") + spec.encoder + " encoder", AVERROR(ENOMEM));
  AVCodecContext* c = e.codec.get();
  c->width = width;
  c->height = height;
  c->pix_fmt = spec.pixels;
  c->sample_aspect_ratio = AVRational{1, 1};
  c->time_base = time_base;
  c->framerate = av_d2q(options.fps, 100000);
  c->thread_count = 0;  // the encoder's own choice from the cores, as the ffmpeg command's
  if (spec.yuv) {
    c->color_range = AVCOL_RANGE_MPEG;
    c->color_primaries = AVCOL_PRI_BT709;
    c->color_trc = AVCOL_TRC_BT709;
    c->colorspace = AVCOL_SPC_BT709;
  }
  if ((muxer->oformat->flags & AVFMT_GLOBALHEADER) != 0) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  Dictionary codec_options;
  if (format == ClipFormat::kWebm) {
    // Constant quality (crf with no bitrate), libvpx's "good" speed 4, rows in parallel.
    c->bit_rate = 0;
    e.check(av_dict_set(codec_options.address(), "crf", "24", 0), "setting crf");
    e.check(av_dict_set(codec_options.address(), "deadline", "good", 0), "setting deadline");
    e.check(av_dict_set(codec_options.address(), "cpu-used", "4", 0), "setting cpu-used");
    e.check(av_dict_set(codec_options.address(), "row-mt", "1", 0), "setting row-mt");
  } else if (format == ClipFormat::kMov) {
    e.check(av_dict_set(codec_options.address(), "profile", "4444", 0), "setting profile");
  } else if (format == ClipFormat::kWebp) {
    e.check(av_dict_set(codec_options.address(), "quality", "90", 0), "setting quality");
  }
  e.check(avcodec_open2(c, codec, codec_options.address()),
          std::string("opening the ") + spec.encoder + " encoder");
  if (codec_options.count() != 0) {
    e.fail(std::string("the ") + spec.encoder + " encoder ignored an option");
  }
  e.stream->time_base = time_base;  // a hint: the muxer picks its own in write_header
  e.stream->avg_frame_rate = c->framerate;
  e.check(avcodec_parameters_from_context(e.stream->codecpar, c),
          "copying the encoder parameters to the stream");
  e.filtered.reset(av_frame_alloc());
  e.packet.reset(av_packet_alloc());
  if (!e.filtered || !e.packet) e.fail("allocating a frame", AVERROR(ENOMEM));

  // "file:" so that the path is always a file system path, never a protocol URL.
  e.check(avio_open2(&muxer->pb, std::string("file:").append(e.written).c_str(), AVIO_FLAG_WRITE,
                     nullptr, nullptr),
          "opening for writing");
  Dictionary muxer_options;
  if (format == ClipFormat::kGif || format == ClipFormat::kWebp) {
    e.check(av_dict_set(muxer_options.address(), "loop", "0", 0), "setting the clip to loop");
  } else if (format == ClipFormat::kMov) {
    // The colour tags in a 'colr' atom, which players and editors read.
    e.check(av_dict_set(muxer_options.address(), "movflags", "write_colr", 0),
            "asking the MOV muxer for colour tags");
  }
  e.check(avformat_write_header(muxer, muxer_options.address()), "writing the " + name + " header");
  if (muxer_options.count() != 0) e.fail("the " + name + " muxer ignored an option");
  e.flush_io("writing the " + name + " header");
  e.start_encoding();
  encoder_ = std::move(encoder);
}

EncodedClipSink::~EncodedClipSink() {
  // Without close() the clip is incomplete: the temporary file goes, the target stays.
  failed_ = true;
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() is where errors are reported.
  }
}

void EncodedClipSink::write(const Image& frame, std::size_t index) {
  const std::string what = std::string("frame ").append(std::to_string(index));
  if (!encoder_) {
    throw SinkError(path_ + ": " + what + " written after the " +
                    std::string(clip_format_name(format_)) + " was closed");
  }
  if (frame.width != width_ || frame.height != height_ ||
      frame.rgba.size() != frame.stride() * static_cast<std::size_t>(height_)) {
    failed_ = true;
    throw SinkError(path_ + ": " + what + " is " + std::to_string(frame.width) + "x" +
                    std::to_string(frame.height) + ", the clip is " + std::to_string(width_) + "x" +
                    std::to_string(height_));
  }
  Encoder& e = *encoder_;
  try {
    e.encoding_error.rethrow();  // an earlier frame's, found by the encoding thread
    std::unique_ptr<AVFrame, FrameFree> input(av_frame_alloc());
    if (!input) e.fail("allocating " + what, AVERROR(ENOMEM));
    input->format = AV_PIX_FMT_RGBA;
    input->width = width_;
    input->height = height_;
    input->sample_aspect_ratio = AVRational{1, 1};
    // Frame k at k/fps, rounded to the time base: GIF's whole centiseconds (delays of 3 and 4
    // cs at 30 fps) keep the clip's length.
    const AVRational tb = time_base_of(format_, fps_);
    input->pts = format_ == ClipFormat::kGif || format_ == ClipFormat::kWebp
                     ? std::llround(static_cast<double>(tb.den) *
                                    static_cast<double>(frames_written_) / fps_)
                     : static_cast<std::int64_t>(frames_written_);
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

void EncodedClipSink::close() {
  if (!encoder_) return;
  // Whatever happens below, the sink is closed afterwards and every libav object is freed
  // (with the temporary file, unless it was put in place).
  const std::unique_ptr<Encoder> encoder = std::move(encoder_);
  Encoder& e = *encoder;
  if (failed_) e.fail("the clip is incomplete (a frame failed); nothing was written");
  if (frames_written_ == 0) e.fail("no frame to write; nothing was written");
  e.check(av_buffersrc_add_frame(e.source, nullptr), "finishing the filters");
  e.drain_filters("encoding the frames");
  e.stop_encoding();
  e.encoding_error.rethrow();
  e.encode(nullptr, "flushing the encoder");
  e.check(av_write_trailer(e.format.get()), "writing the trailer");
  e.flush_io("writing the clip");
  e.check(avio_closep(&e.format->pb), "closing the file");
  if (e.written != e.path && std::rename(e.written.c_str(), e.path.c_str()) != 0) {
    e.fail(std::string("putting the clip in place: ").append(std::strerror(errno)));
  }
  e.committed = true;
}

}  // namespace rugosim
