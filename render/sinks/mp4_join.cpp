#include "render/sinks/mp4_join.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavformat/avio.h>
#include <libavutil/dict.h>
#include <libavutil/mathematics.h>
}

#include "render/sinks/frame_sink.h"
#include "render/sinks/libav_support.h"

namespace rugosim {
namespace {

struct InputClose {
  void operator()(AVFormatContext* format) const { avformat_close_input(&format); }
};
using Input = std::unique_ptr<AVFormatContext, InputClose>;

struct OpenedInput {
  Input format;
  int stream = -1;
};

OpenedInput open_input(const std::string& path) {
  const LibavErrors e{path};
  AVFormatContext* raw = nullptr;
  e.check(avformat_open_input(&raw, std::string("file:").append(path).c_str(), nullptr, nullptr),
          "opening the clip");
  OpenedInput in{Input(raw), -1};
  e.check(avformat_find_stream_info(in.format.get(), nullptr), "reading the clip's streams");
  in.stream = av_find_best_stream(in.format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (in.stream < 0 || in.format->streams[in.stream]->codecpar->codec_id != AV_CODEC_ID_H264) {
    e.fail("no H.264 video stream");
  }
  return in;
}

bool same_stream(const AVCodecParameters& a, const AVCodecParameters& b) {
  return a.codec_id == b.codec_id && a.width == b.width && a.height == b.height &&
         a.format == b.format && a.extradata_size == b.extradata_size &&
         (a.extradata_size == 0 ||
          std::memcmp(a.extradata, b.extradata, static_cast<std::size_t>(a.extradata_size)) == 0);
}

}  // namespace

std::string mp4_comment(const std::string& path) {
  const OpenedInput in = open_input(path);
  const AVDictionaryEntry* entry = av_dict_get(in.format->metadata, "comment", nullptr, 0);
  return entry != nullptr ? std::string(entry->value) : std::string();
}

JoinedClip join_mp4(const std::vector<std::string>& inputs, const std::string& output) {
  const LibavErrors out_errors{output};
  if (inputs.empty()) out_errors.fail("no clips to join");
  OpenedInput first = open_input(inputs.front());
  const AVStream* first_stream = first.format->streams[first.stream];

  AVFormatContext* raw = nullptr;
  out_errors.check(avformat_alloc_output_context2(&raw, nullptr, "mp4", nullptr),
                   "creating the MP4 muxer");
  std::unique_ptr<AVFormatContext, FormatContextFree> out(raw);
  AVStream* stream = avformat_new_stream(out.get(), nullptr);
  if (stream == nullptr) out_errors.fail("adding the video stream");
  out_errors.check(avcodec_parameters_copy(stream->codecpar, first_stream->codecpar),
                   "copying the stream's parameters");
  stream->codecpar->codec_tag = 0;
  stream->time_base = first_stream->time_base;
  stream->avg_frame_rate = first_stream->avg_frame_rate;
  out_errors.check(avio_open2(&out->pb, std::string("file:").append(output).c_str(),
                              AVIO_FLAG_WRITE, nullptr, nullptr),
                   "opening the file");
  Dictionary options;
  av_dict_set(options.address(), "movflags", kFragmentedMovFlags, 0);
  out_errors.check(avformat_write_header(out.get(), options.address()), "writing the MP4 header");

  std::unique_ptr<AVPacket, PacketFree> packet(av_packet_alloc());
  if (!packet) out_errors.fail("allocating a packet");
  JoinedClip joined;
  const std::int64_t first_start =
      first_stream->start_time == AV_NOPTS_VALUE
          ? 0
          : av_rescale_q(first_stream->start_time, first_stream->time_base, stream->time_base);
  std::int64_t offset = 0;  // in the output stream's time base: where the last clip ended
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    OpenedInput in = k == 0 ? std::move(first) : open_input(inputs[k]);
    const AVStream* in_stream = in.format->streams[in.stream];
    if (!same_stream(*in_stream->codecpar, *stream->codecpar)) {
      LibavErrors{inputs[k]}.fail("its stream differs from " + inputs.front() +
                                  "'s (size, codec or H.264 headers): encoded with other "
                                  "settings, or without stitchable");
    }
    // The clip's first frame is shown where the previous one's last ended: its timestamps move
    // by that end less its own first presentation time (an encoder with B-frames starts a clip
    // a few frames late; the first clip keeps that start, as a single render has it).
    const std::int64_t start =
        in_stream->start_time == AV_NOPTS_VALUE
            ? 0
            : av_rescale_q(in_stream->start_time, in_stream->time_base, stream->time_base);
    const std::int64_t shift = k == 0 ? 0 : offset - start;
    std::int64_t end = offset;
    const LibavErrors in_errors{inputs[k]};
    for (;;) {
      const int read = av_read_frame(in.format.get(), packet.get());
      if (read == AVERROR_EOF) break;
      in_errors.check(read, "reading a packet");
      if (packet->stream_index != in.stream) {
        av_packet_unref(packet.get());
        continue;
      }
      av_packet_rescale_ts(packet.get(), in_stream->time_base, stream->time_base);
      if (packet->pts != AV_NOPTS_VALUE) packet->pts += shift;
      if (packet->dts != AV_NOPTS_VALUE) packet->dts += shift;
      end = std::max(end, packet->pts + packet->duration);
      packet->stream_index = 0;
      packet->pos = -1;
      ++joined.frames;
      out_errors.check(av_interleaved_write_frame(out.get(), packet.get()), "writing a packet");
    }
    offset = end;
  }
  out_errors.check(av_write_trailer(out.get()), "writing the MP4 trailer");
  out_errors.flush_io(out->pb, "closing the file");
  joined.seconds = static_cast<double>(offset - first_start) * av_q2d(stream->time_base);
  return joined;
}

}  // namespace rugosim
