#include "render/snapshot/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rugosim {
namespace {

void check_rule(const CompareRule& rule) {
  if (rule.threshold < 0 || rule.threshold > 255) {
    throw std::invalid_argument(std::string("image comparison: the threshold must be 0..255, got ")
                                    .append(std::to_string(rule.threshold)));
  }
  if (!std::isfinite(rule.max_share) || rule.max_share < 0.0 || rule.max_share > 1.0) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", rule.max_share);
    throw std::invalid_argument(
        std::string("image comparison: the largest share of differing pixels must be in [0, 1], "
                    "got ")
            .append(text));
  }
}

void check_image(const Image& image, const char* which) {
  if (image.width < 0 || image.height < 0 ||
      image.rgba.size() != Image::bytes(image.width, image.height)) {
    throw std::invalid_argument(
        std::string("image comparison: the ")
            .append(which)
            .append(" image's pixels do not hold width × height × 4 bytes"));
  }
}

int abs_diff(std::uint8_t a, std::uint8_t b) {
  return a > b ? a - b : b - a;
}

// The largest difference in R, G and B of the pixels at `a` and `b`.
// Alpha too: frames of a transparent background differ there as well (opaque frames have 255).
int channel_diff(const std::uint8_t* a, const std::uint8_t* b) {
  return std::max(std::max(abs_diff(a[0], b[0]), abs_diff(a[1], b[1])),
                  std::max(abs_diff(a[2], b[2]), abs_diff(a[3], b[3])));
}

// Pixels above this are marked red and bounded by the box: every difference under an exact
// rule, those beyond the threshold otherwise.
int box_threshold(const CompareRule& rule) {
  return rule.exact ? 0 : rule.threshold;
}

std::string size_text(int width, int height) {
  return std::to_string(width).append("×").append(std::to_string(height));
}

std::string point_text(int x, int y) {
  return std::string("(")
      .append(std::to_string(x))
      .append(", ")
      .append(std::to_string(y))
      .append(")");
}

// A percentage with three significant digits in fixed notation (no exponent: 0.0000482 rather
// than 4.82e-05), trailing zeros dropped.
std::string percent_text(double share) {
  const double percent = share * 100.0;
  if (percent == 0.0) return "0";
  const int magnitude = static_cast<int>(std::floor(std::log10(percent)));
  const int decimals = std::clamp(2 - magnitude, 0, 12);
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, percent);
  std::string out(text);
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0')
      out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  return out;
}

void set_pixel(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = r;
  p[1] = g;
  p[2] = b;
  p[3] = 255;
}

}  // namespace

CompareResult compare_images(const Image& golden, const Image& actual, const CompareRule& rule) {
  check_rule(rule);
  check_image(golden, "golden");
  check_image(actual, "actual");
  CompareResult result;
  result.golden_width = golden.width;
  result.golden_height = golden.height;
  result.actual_width = actual.width;
  result.actual_height = actual.height;
  if (golden.width != actual.width || golden.height != actual.height) {
    result.size_mismatch = true;
    return result;
  }

  const int width = golden.width;
  const int height = golden.height;
  const std::size_t stride = golden.stride();
  const int threshold = rule.threshold;
  const int boxed = box_threshold(rule);
  std::size_t differing = 0;
  std::size_t failing = 0;
  int worst = 0;
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* g = golden.rgba.data() + static_cast<std::size_t>(y) * stride;
    const std::uint8_t* a = actual.rgba.data() + static_cast<std::size_t>(y) * stride;
    // Frames under test mostly match: a row equal in all four channels costs one memcmp.
    if (std::memcmp(g, a, stride) == 0) continue;
    // A failing frame may differ everywhere (noise), so the row is counted in a loop free of
    // branches that GCC vectorises; only then are the ends of its boxed run searched for.
    unsigned row_differing = 0;
    unsigned row_failing = 0;
    unsigned row_boxed = 0;
    int row_worst = 0;
    for (int x = 0; x < width; ++x) {
      const int d = channel_diff(g + 4 * x, a + 4 * x);
      row_differing += d != 0 ? 1U : 0U;
      row_failing += d > threshold ? 1U : 0U;
      row_boxed += d > boxed ? 1U : 0U;
      row_worst = std::max(row_worst, d);
    }
    differing += row_differing;
    failing += row_failing;
    if (row_boxed > 0) {
      int x0 = 0;
      while (channel_diff(g + 4 * x0, a + 4 * x0) <= boxed)
        ++x0;
      int x1 = width - 1;
      while (channel_diff(g + 4 * x1, a + 4 * x1) <= boxed)
        --x1;
      if (result.box_y0 < 0) {
        result.box_y0 = y;
        result.box_x0 = x0;
        result.box_x1 = x1;
      }
      result.box_y1 = y;
      result.box_x0 = std::min(result.box_x0, x0);
      result.box_x1 = std::max(result.box_x1, x1);
    }
    if (row_worst > worst) {
      // At most 255 times in all: find where in the row the new worst is first reached.
      worst = row_worst;
      int x = 0;
      while (channel_diff(g + 4 * x, a + 4 * x) != row_worst)
        ++x;
      result.worst_x = x;
      result.worst_y = y;
    }
  }

  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  result.differing_pixels = differing;
  result.failing_pixels = failing;
  result.worst = worst;
  result.identical = differing == 0;
  result.failing_share =
      pixels == 0 ? 0.0 : static_cast<double>(failing) / static_cast<double>(pixels);
  result.passed = result.identical || (!rule.exact && result.failing_share <= rule.max_share);
  return result;
}

Image difference_image(const Image& golden, const Image& actual, const CompareRule& rule) {
  const CompareResult result = compare_images(golden, actual, rule);
  Image out(actual.width, actual.height);
  if (result.size_mismatch) {
    for (int y = 0; y < out.height; ++y) {
      for (int x = 0; x < out.width; ++x)
        set_pixel(out, x, y, 255, 0, 0);
    }
    return out;
  }

  const int boxed = box_threshold(rule);
  const std::uint8_t* g = golden.rgba.data();
  const std::uint8_t* a = actual.rgba.data();
  std::uint8_t* o = out.rgba.data();
  const std::size_t pixels = out.rgba.size() / 4;
  for (std::size_t i = 0; i < pixels; ++i, g += 4, a += 4, o += 4) {
    const int d = channel_diff(g, a);
    // Rec. 709 luma in 8-bit fixed point (54 + 183 + 19 = 256), then three quarters of the way
    // to white, rounded: 0 → 191, 255 → 255.
    const unsigned luma = (54U * a[0] + 183U * a[1] + 19U * a[2] + 128U) >> 8;
    const auto grey = static_cast<std::uint8_t>((luma + 3U * 255U + 2U) / 4U);
    // Selects rather than branches, so that a frame differing everywhere costs no more.
    const bool marked = d > 0;
    const bool red = d > boxed;
    o[0] = marked ? std::uint8_t{255} : grey;
    o[1] = red ? std::uint8_t{0} : (marked ? std::uint8_t{165} : grey);
    o[2] = marked ? std::uint8_t{0} : grey;
    o[3] = 255;
  }

  if (result.box_x0 >= 0) {
    // The rectangle's lines 3 px outside the box (two clear pixels between); a side that falls
    // outside the image is not drawn.
    constexpr int kMargin = 3;
    const int x0 = result.box_x0 - kMargin;
    const int y0 = result.box_y0 - kMargin;
    const int x1 = result.box_x1 + kMargin;
    const int y1 = result.box_y1 + kMargin;
    const int cx0 = std::max(x0, 0);
    const int cx1 = std::min(x1, out.width - 1);
    const int cy0 = std::max(y0, 0);
    const int cy1 = std::min(y1, out.height - 1);
    for (int x = cx0; x <= cx1; ++x) {
      if (y0 >= 0) set_pixel(out, x, y0, 255, 0, 0);
      if (y1 < out.height) set_pixel(out, x, y1, 255, 0, 0);
    }
    for (int y = cy0; y <= cy1; ++y) {
      if (x0 >= 0) set_pixel(out, x0, y, 255, 0, 0);
      if (x1 < out.width) set_pixel(out, x1, y, 255, 0, 0);
    }
  }
  return out;
}

std::string describe(const CompareResult& result, const CompareRule& rule) {
  if (result.size_mismatch) {
    return std::string("size mismatch: golden ")
        .append(size_text(result.golden_width, result.golden_height))
        .append(", actual ")
        .append(size_text(result.actual_width, result.actual_height));
  }
  if (result.identical) return "identical";

  const std::size_t pixels = static_cast<std::size_t>(result.golden_width) *
                             static_cast<std::size_t>(result.golden_height);
  const std::size_t counted = rule.exact ? result.differing_pixels : result.failing_pixels;
  const double share = rule.exact ? (pixels == 0 ? 0.0
                                                 : static_cast<double>(result.differing_pixels) /
                                                       static_cast<double>(pixels))
                                  : result.failing_share;
  std::string text = std::to_string(counted);
  text.append(counted == 1 ? " pixel differs (" : " pixels differ (")
      .append(percent_text(share))
      .append("%, rule: ");
  if (rule.exact) {
    text.append("exact");
  } else {
    text.append("threshold ")
        .append(std::to_string(rule.threshold))
        .append(", max ")
        .append(percent_text(rule.max_share))
        .append("%");
  }
  text.append(")");
  if (!rule.exact && result.differing_pixels > result.failing_pixels) {
    text.append(", ")
        .append(std::to_string(result.differing_pixels - result.failing_pixels))
        .append(" more within the threshold");
  }
  text.append(", worst ")
      .append(std::to_string(result.worst))
      .append(" at ")
      .append(point_text(result.worst_x, result.worst_y));
  if (result.box_x0 >= 0) {
    text.append(", in the box ")
        .append(point_text(result.box_x0, result.box_y0))
        .append("–")
        .append(point_text(result.box_x1, result.box_y1));
  }
  return text;
}

}  // namespace rugosim
