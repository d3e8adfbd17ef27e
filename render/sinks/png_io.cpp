// libpng reports errors by longjmp: every function below that calls setjmp holds only plain
// data (no object with a destructor, no C++ exception crossing libpng's C frames), reports
// failure by its return value, and leaves throwing to its C++ caller. Callbacks that libpng
// calls (memory source and sink) catch what they could throw and call png_error outside the
// catch block.
#include "render/sinks/png_io.h"

#include <array>
#include <cerrno>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <png.h>

#include "render/sinks/atomic_output_file.h"

namespace rugosim {
namespace {

constexpr std::size_t kMessageSize = 256;
// Larger than any frame we render (8K UHD is 2^25 pixels); keeps a hostile header from asking
// for gigabytes.
constexpr std::uint64_t kMaxDecodedPixels = std::uint64_t{1} << 26;

// libpng's error message, kept in plain storage so that it survives the longjmp.
struct ErrorText {
  char text[kMessageSize] = {};
};

void keep_message(ErrorText& error, const char* message) {
  std::snprintf(error.text, sizeof error.text, "%s", message != nullptr ? message : "");
}

extern "C" void on_png_error(png_structp png, png_const_charp message) {
  keep_message(*static_cast<ErrorText*>(png_get_error_ptr(png)), message);
  png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp /*png*/, png_const_charp /*message*/) {
  // Warnings (an unknown chunk, an odd colour profile) do not stop decoding; libpng would
  // print them on stderr.
}

int libpng_filter(PngFilter filter) {
  switch (filter) {
    case PngFilter::kNone:
      return PNG_FILTER_NONE;
    case PngFilter::kSub:
      return PNG_FILTER_SUB;
    case PngFilter::kUp:
      return PNG_FILTER_UP;
    case PngFilter::kAverage:
      return PNG_FILTER_AVG;
    case PngFilter::kPaeth:
      return PNG_FILTER_PAETH;
    case PngFilter::kAll:
      return PNG_ALL_FILTERS;
  }
  return PNG_FILTER_NONE;
}

// ---- Writing ----

struct WriteJob {
  ErrorText error;
  const Image* image = nullptr;
  const PngSettings* settings = nullptr;
  std::vector<std::uint8_t>* out = nullptr;
};

extern "C" void append_to_vector(png_structp png, png_bytep data, std::size_t size) {
  auto* job = static_cast<WriteJob*>(png_get_io_ptr(png));
  bool appended = false;
  try {
    job->out->insert(job->out->end(), data, data + size);
    appended = true;
  } catch (...) {
  }
  if (!appended) png_error(png, "out of memory");
}

extern "C" void flush_nothing(png_structp /*png*/) {}

// The classic write API, for the filter and zlib settings the simplified one does not offer.
bool run_png_write(WriteJob& job) noexcept {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &job.error, on_png_error, on_png_warning);
  if (png == nullptr) {
    keep_message(job.error, "cannot create the libpng write structure");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    keep_message(job.error, "cannot create the libpng info structure");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  const Image& image = *job.image;
  const PngSettings& settings = *job.settings;
  png_set_write_fn(png, &job, append_to_vector, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8,
               settings.keep_alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, libpng_filter(settings.filter));
  png_set_compression_level(png, settings.level);
  if (settings.rle) png_set_compression_strategy(png, Z_RLE);
  // Fewer, larger IDAT chunks and write callbacks than the default 8 KiB.
  png_set_compression_buffer_size(png, std::size_t{1} << 16);
  png_write_info(png, info);
  // Our rows are RGBA; for an RGB file libpng drops the fourth byte of each pixel itself.
  if (!settings.keep_alpha) png_set_filler(png, 0, PNG_FILLER_AFTER);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, image.pixel(0, y));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// ---- Reading ----

struct ReadJob {
  ErrorText error;
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
  bool truncated = false;
  png_structp png = nullptr;
  png_infop info = nullptr;
  png_uint_32 width = 0;
  png_uint_32 height = 0;
};

extern "C" void read_from_memory(png_structp png, png_bytep out, std::size_t size) {
  auto* job = static_cast<ReadJob*>(png_get_io_ptr(png));
  if (size > job->size - job->offset) {
    job->truncated = true;
    png_error(png, "read beyond the end of the data");
  }
  std::memcpy(out, job->data + job->offset, size);
  job->offset += size;
}

// Creates the read structures (destroyed by ReadStructs) and reads the header, setting up the
// transforms to RGBA8.
bool run_png_read_header(ReadJob& job) noexcept {
  job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job.error, on_png_error, on_png_warning);
  if (job.png == nullptr) {
    keep_message(job.error, "cannot create the libpng read structure");
    return false;
  }
  job.info = png_create_info_struct(job.png);
  if (job.info == nullptr) {
    keep_message(job.error, "cannot create the libpng info structure");
    return false;
  }
  png_structp png = job.png;
  png_infop info = job.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &job, read_from_memory);
  png_read_info(png, info);
  const int colour_type = png_get_color_type(png, info);
  // Palette to RGB, gray below 8 bits to 8 bits, tRNS to an alpha channel.
  png_set_expand(png);
  png_set_scale_16(png);
  if ((colour_type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(png);
  if ((colour_type & PNG_COLOR_MASK_ALPHA) == 0 && png_get_valid(png, info, PNG_INFO_tRNS) == 0) {
    png_set_filler(png, 0xff, PNG_FILLER_AFTER);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  job.width = png_get_image_width(png, info);
  job.height = png_get_image_height(png, info);
  if (png_get_rowbytes(png, info) != std::size_t{job.width} * 4) {
    keep_message(job.error, "unexpected row layout after conversion to RGBA8");
    return false;
  }
  return true;
}

bool run_png_read_rows(ReadJob& job, png_bytepp rows) noexcept {
  png_structp png = job.png;
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

// Destroys the read structures of a ReadJob, however decoding ends.
class ReadStructs {
 public:
  explicit ReadStructs(ReadJob& job) : job_(job) {}
  ~ReadStructs() {
    if (job_.png != nullptr) png_destroy_read_struct(&job_.png, &job_.info, nullptr);
  }
  ReadStructs(const ReadStructs&) = delete;
  ReadStructs& operator=(const ReadStructs&) = delete;

 private:
  ReadJob& job_;
};

PngReadError read_error(std::string_view name, const ReadJob& job) {
  std::string message(name);
  if (job.truncated) return PngReadError(message.append(": truncated PNG data"));
  return PngReadError(message.append(": invalid PNG: ").append(job.error.text));
}

// ---- Files ----

PngReadError read_file_error(const std::string& path, const char* what, int error_number) {
  return PngReadError(
      std::string(path).append(": ").append(what).append(": ").append(std::strerror(error_number)));
}

struct FileCloser {
  int fd;
  explicit FileCloser(int descriptor) : fd(descriptor) {}
  ~FileCloser() {
    if (fd >= 0) ::close(fd);
  }
  FileCloser(const FileCloser&) = delete;
  FileCloser& operator=(const FileCloser&) = delete;
};

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, const PngSettings& settings) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != std::size_t{4} * static_cast<std::size_t>(image.width) *
                               static_cast<std::size_t>(image.height)) {
    throw std::invalid_argument(
        "encode_png: the image must be non-empty, with width × height × 4 bytes");
  }
  if (settings.level < 0 || settings.level > 9) {
    throw std::invalid_argument(std::string("encode_png: the compression level must be 0..9, got ")
                                    .append(std::to_string(settings.level)));
  }
  std::vector<std::uint8_t> out;
  // Flat frames compress to a few percent; this avoids most reallocations.
  out.reserve(image.rgba.size() / 32 + 1024);
  WriteJob job;
  job.image = &image;
  job.settings = &settings;
  job.out = &out;
  if (!run_png_write(job)) {
    throw std::runtime_error(std::string("PNG encoder: ").append(job.error.text));
  }
  return out;
}

void write_png_file(const std::string& path, const Image& image, const PngSettings& settings) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encode_png(image, settings);
  } catch (const std::runtime_error& error) {
    throw SinkError(std::string(path).append(": ").append(error.what()));
  }
  write_file_atomically(path, bytes, AtomicOutputFile::Flush::kRenameOnly);
}

Image decode_png(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (bytes.empty()) throw PngReadError(std::string(name).append(": not a PNG file (empty)"));
  if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) {
    throw PngReadError(std::string(name).append(": not a PNG file"));
  }
  ReadJob job;
  job.data = bytes.data();
  job.size = bytes.size();
  const ReadStructs structs(job);
  if (!run_png_read_header(job)) throw read_error(name, job);
  if (std::uint64_t{job.width} * job.height > kMaxDecodedPixels) {
    throw PngReadError(std::string(name)
                           .append(": image too large (")
                           .append(std::to_string(job.width))
                           .append("×")
                           .append(std::to_string(job.height))
                           .append(" pixels, at most 2^26 pixels are read)"));
  }
  Image image(static_cast<int>(job.width), static_cast<int>(job.height));
  std::vector<png_bytep> rows;
  rows.reserve(job.height);
  for (int y = 0; y < image.height; ++y)
    rows.push_back(image.pixel(0, y));
  if (!run_png_read_rows(job, rows.data())) throw read_error(name, job);
  return image;
}

Image read_png_file(const std::string& path) {
  const FileCloser file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.fd < 0) throw read_file_error(path, "cannot open", errno);
  std::vector<std::uint8_t> bytes;
  struct stat status {};
  if (::fstat(file.fd, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0) {
    bytes.reserve(static_cast<std::size_t>(status.st_size));
  }
  std::array<std::uint8_t, std::size_t{1} << 16> buffer{};
  for (;;) {
    const ssize_t got = ::read(file.fd, buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw read_file_error(path, "cannot read", errno);
    if (got == 0) break;
    bytes.insert(bytes.end(), buffer.begin(), buffer.begin() + got);
  }
  return decode_png(bytes, path);
}

std::optional<PngFilter> parse_png_filter(std::string_view name) {
  for (const PngFilter filter : {PngFilter::kNone, PngFilter::kSub, PngFilter::kUp,
                                 PngFilter::kAverage, PngFilter::kPaeth, PngFilter::kAll}) {
    if (png_filter_name(filter) == name) return filter;
  }
  return std::nullopt;
}

std::string_view png_filter_name(PngFilter filter) {
  switch (filter) {
    case PngFilter::kNone:
      return "none";
    case PngFilter::kSub:
      return "sub";
    case PngFilter::kUp:
      return "up";
    case PngFilter::kAverage:
      return "average";
    case PngFilter::kPaeth:
      return "paeth";
    case PngFilter::kAll:
      return "all";
  }
  return "none";
}

}  // namespace rugosim
