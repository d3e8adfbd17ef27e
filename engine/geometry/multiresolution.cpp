#include "engine/geometry/multiresolution.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace rugosim {
namespace {

// Update weight of the lifting scheme: the one value for which c_i = s_i + alpha (d_{i-1} + d_i)
// expands to the Samavati-Bartels least-squares filter, e.g. f_{2i} gets 2 - 2 alpha = 52/49
// and f_{2i+3} gets alpha / 4 = 23/196.
constexpr double kAlpha = 23.0 / 49.0;

// The smallest control count of a periodic cubic B-spline.
constexpr std::size_t kMinPoints = 4;

// Throws unless 0 <= level < end; `coarser` is the curve's level count L, for the message.
void check_level(int level, int end, int coarser, const char* what) {
  if (level < 0 || level >= end) {
    throw std::out_of_range(std::string("multiresolution ") + what + " level " +
                            std::to_string(level) + " is outside [0, " + std::to_string(end) +
                            ") for a curve with " + std::to_string(coarser) + " coarser levels");
  }
}

}  // namespace

WaveletLevel decompose(std::span<const Vec2> fine) {
  const std::size_t n = fine.size();
  if (n % 2 != 0 || n < 2 * kMinPoints) {
    throw std::invalid_argument(
        "wavelet decomposition needs an even number of at least 8 control points, got " +
        std::to_string(n));
  }
  const std::size_t m = n / 2;
  // Undo the vertex rule of subdivision, f_{2i} = s_i / 2 + (f_{2i-1} + f_{2i+1}) / 4.
  std::vector<Vec2> s(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2& before = fine[(2 * i + n - 1) % n];
    const Vec2& after = fine[2 * i + 1];
    s[i] = 2.0 * fine[2 * i] - (before + after) / 2.0;
  }
  // Details: what the odd points have beyond the midpoints of the even predictions.
  WaveletLevel level;
  level.details.resize(m);
  for (std::size_t i = 0; i < m; ++i)
    level.details[i] = fine[2 * i + 1] - (s[i] + s[(i + 1) % m]) / 2.0;
  // Update: fold the neighbouring details back so the coarse curve fits the fine one in the
  // least-squares sense instead of interpolating every other point.
  level.coarse.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2& before = level.details[(i + m - 1) % m];
    level.coarse[i] = s[i] + kAlpha * (before + level.details[i]);
  }
  return level;
}

std::vector<Vec2> reconstruct(std::span<const Vec2> coarse, std::span<const Vec2> details) {
  const std::size_t m = coarse.size();
  if (details.size() != m) {
    throw std::invalid_argument(
        "wavelet reconstruction needs as many details as coarse points, got " + std::to_string(m) +
        " coarse points and " + std::to_string(details.size()) + " details");
  }
  if (m < kMinPoints) {
    throw std::invalid_argument(
        "wavelet reconstruction needs at least 4 coarse control points, got " + std::to_string(m));
  }
  // The analysis steps undone in reverse order, each with the same arithmetic as its forward
  // twin so that only rounding separates the result from the input of decompose.
  std::vector<Vec2> s(m);
  for (std::size_t i = 0; i < m; ++i)
    s[i] = coarse[i] - kAlpha * (details[(i + m - 1) % m] + details[i]);
  const std::size_t n = 2 * m;
  std::vector<Vec2> fine(n);
  for (std::size_t i = 0; i < m; ++i)
    fine[2 * i + 1] = details[i] + (s[i] + s[(i + 1) % m]) / 2.0;
  for (std::size_t i = 0; i < m; ++i)
    fine[2 * i] = s[i] / 2.0 + (fine[(2 * i + n - 1) % n] + fine[2 * i + 1]) / 4.0;
  return fine;
}

int max_wavelet_levels(std::size_t n) {
  int levels = 0;
  while (n % 2 == 0 && n / 2 >= kMinPoints) {
    n /= 2;
    ++levels;
  }
  return levels;
}

Multiresolution::Multiresolution(std::vector<Vec2> finest, int max_levels) {
  if (finest.size() < kMinPoints) {
    throw std::invalid_argument("a multiresolution curve needs at least 4 control points, got " +
                                std::to_string(finest.size()));
  }
  for (std::size_t i = 0; i < finest.size(); ++i) {
    if (!finest[i].allFinite()) {
      throw std::invalid_argument("multiresolution control point " + std::to_string(i) +
                                  " is not finite");
    }
  }
  if (max_levels < kAllLevels) {
    throw std::invalid_argument("multiresolution max_levels must be >= 0, or -1 for all, got " +
                                std::to_string(max_levels));
  }
  const int possible = max_wavelet_levels(finest.size());
  const int levels = max_levels == kAllLevels || max_levels > possible ? possible : max_levels;
  const auto count = static_cast<std::size_t>(levels);
  levels_.reserve(count + 1);
  details_.reserve(count);
  levels_.push_back(std::move(finest));
  for (std::size_t k = 0; k < count; ++k) {
    WaveletLevel next = decompose(levels_.back());
    levels_.push_back(std::move(next.coarse));
    details_.push_back(std::move(next.details));
  }
}

const std::vector<Vec2>& Multiresolution::control_points(int level) const {
  check_level(level, level_count() + 1, level_count(), "control point");
  return levels_[static_cast<std::size_t>(level)];
}

const std::vector<Vec2>& Multiresolution::details(int level) const {
  check_level(level, level_count(), level_count(), "detail");
  return details_[static_cast<std::size_t>(level)];
}

std::vector<Vec2> Multiresolution::reconstruct_finest(int from_level) const {
  check_level(from_level, level_count() + 1, level_count(), "reconstruction");
  std::vector<Vec2> points = levels_[static_cast<std::size_t>(from_level)];
  for (int k = from_level - 1; k >= 0; --k)
    points = reconstruct(points, details_[static_cast<std::size_t>(k)]);
  return points;
}

}  // namespace rugosim
