// PNG files in and out of memory with libpng: encoding with the compression settings frames
// need (fast over small), atomic file writes, and reading any PNG back as RGBA8.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim {

// The PNG row filter libpng applies before deflate. kAll lets libpng choose one per row (the
// smallest files, the slowest encode).
enum class PngFilter { kNone, kSub, kUp, kAverage, kPaeth, kAll };

struct PngSettings {
  int level = 1;  // zlib compression level, 0 (store) .. 9 (smallest)
  PngFilter filter = PngFilter::kUp;
  // zlib's Z_RLE strategy: matches only repeats of the previous byte, which after the Up
  // filter is what a mostly flat frame consists of. Measured on a 1920×1080 frame (flat
  // background, six filled anti-aliased discs with outlines; x86-64, zlib 1.2.13, libpng
  // 1.6.39, one core): level 1 + up + RLE 14.1 ms, 70 kB; level 1 + up without RLE 14.0 ms,
  // 84 kB; level 6 + up without RLE 26.5 ms, 69 kB; libpng's defaults (level 6, adaptive
  // filters) 48 ms, 66 kB. So RLE gives level-6 sizes at level-1 speed (with RLE the level
  // hardly matters: level 6 + up + RLE is also 13.6 ms, 70 kB). At level 1 most of
  // the time is libpng's filtering and RGBA→RGB packing and zlib's checksums, not matching. Without
  // a filter RLE is a poor match: an RGB background repeats every 3 bytes, not every byte (1.8 MB,
  // 41 ms). false: libpng's default strategy.
  bool rle = true;
  bool keep_alpha = false;  // write RGBA; when false RGB (frames are opaque), alpha dropped
};

// A PNG that cannot be read: the message names the file (or "PNG data" for memory) and what is
// wrong ("not a PNG file", "truncated PNG data", or libpng's own message).
class PngReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The PNG file of `image` in memory. Throws std::invalid_argument when the image is empty or
// its pixel buffer does not hold width × height × 4 bytes, and std::runtime_error when libpng
// fails (out of memory).
std::vector<std::uint8_t> encode_png(const Image& image, const PngSettings& settings);

// Encodes `image` and writes it to `path` atomically (atomic_output_file.h): to a temporary file
// beside it, renamed over `path` once complete, so that an interrupted run never leaves a truncated
// PNG (the temporary file is removed on failure; a symbolic link is kept and its target replaced).
// An existing `path` that is not a regular file (a device, a FIFO), or any path under /dev or /proc
// (/dev/stdout, /dev/full), is written directly. No fsync: the rename protects against the process
// stopping, not against the machine losing power, which would cost a disk flush per frame. Throws
// SinkError("<path>: <what failed>: <system reason>"), and std::invalid_argument as encode_png.
void write_png_file(const std::string& path, const Image& image, const PngSettings& settings);

// Any PNG (gray, gray + alpha, palette, RGB, RGBA; 1 to 16 bits per sample; tRNS transparency;
// interlaced or not) as RGBA8: samples are taken as stored (no gamma or colour-space
// conversion), 16-bit samples rounded to 8 bits (v × 255 / 65535 to nearest), low-depth gray
// scaled to 0..255, alpha 255 where the file has none. Images over 2^26 pixels are refused.
// `name` is what error messages call the data. Throws PngReadError.
Image decode_png(std::span<const std::uint8_t> bytes, std::string_view name = "PNG data");
// decode_png of the file's contents; errors name `path`. Throws PngReadError.
Image read_png_file(const std::string& path);

// "none", "sub", "up", "average", "paeth", "all" (as png_filter_name gives them); nullopt
// for anything else.
std::optional<PngFilter> parse_png_filter(std::string_view name);
std::string_view png_filter_name(PngFilter filter);

}  // namespace rugosim
