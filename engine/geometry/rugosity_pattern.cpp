#include "engine/geometry/rugosity_pattern.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/core/random.h"

namespace rugosim {

namespace {
constexpr std::array<std::string_view, 4> kNames = {"type_1", "type_2", "type_3", "type_4"};
}  // namespace

std::optional<RugosityPattern> parse_rugosity_pattern(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (name == kNames[i]) return static_cast<RugosityPattern>(i);
  }
  return std::nullopt;
}

std::string_view rugosity_pattern_name(RugosityPattern pattern) {
  return kNames[static_cast<std::size_t>(pattern)];
}

std::vector<double> pattern_sigmas(RugosityPattern pattern, double sigma, std::size_t n,
                                   std::uint64_t seed) {
  if (!std::isfinite(sigma) || sigma < 0.0) {
    throw std::invalid_argument("pattern sigma must be finite and >= 0, got " +
                                std::to_string(sigma));
  }
  if (n == 0) throw std::invalid_argument("a rugosity pattern needs at least one segment");
  std::vector<double> out(n, sigma);
  const double count = static_cast<double>(n);
  switch (pattern) {
    case RugosityPattern::kConstant:
      break;
    case RugosityPattern::kGradient:
      for (std::size_t j = 0; j < n; ++j) {
        const double u = (static_cast<double>(j) + 0.5) / count;
        const double rise = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * u));
        out[j] = sigma * (kPatternSmoothShare + (1.0 - kPatternSmoothShare) * rise);
      }
      break;
    case RugosityPattern::kRandom: {
      Rng rng(seed);
      for (double& s : out)
        s = sigma * rng.uniform(kPatternSmoothShare, 1.0);
      break;
    }
    case RugosityPattern::kPatches: {
      const std::size_t patches =
          std::max<std::size_t>(2, 2 * static_cast<std::size_t>(std::lround(count / 16.0)));
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t patch = j * patches / n;
        out[j] = patch % 2 == 0 ? sigma : sigma * kPatternSmoothShare;
      }
      break;
    }
  }
  return out;
}

}  // namespace rugosim
