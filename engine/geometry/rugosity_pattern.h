// The rugosity pattern library (paper §4.4, fig. 7). The paper's figure 7 values cannot be
// recovered from the text, so rugosim defines its own four patterns, each a shape in (0, 1]
// scaled by the scene's `sigma` (the largest σ of the pattern):
//   type_1  constant:          σ_j = s
//   type_2  smooth gradient:   σ_j = s·(0.1 + 0.9·(1 − cos 2πu_j)/2), u_j = (j + 1/2)/n;
//                              smooth (0.1 s) at the start of the boundary, roughest halfway
//   type_3  seeded random:     σ_j = s·U_j, U_j independent and uniform in [0.1, 1)
//   type_4  patches:           an even number P = max(2, 2·round(n/16)) of equal runs of
//                              segments, alternating rough (s) and smooth (0.1 s)
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace rugosim {

enum class RugosityPattern { kConstant, kGradient, kRandom, kPatches };

// The smooth share of a pattern: the smallest σ relative to the largest.
inline constexpr double kPatternSmoothShare = 0.1;

// "type_1".."type_4" -> pattern; nullopt for any other name.
std::optional<RugosityPattern> parse_rugosity_pattern(std::string_view name);
std::string_view rugosity_pattern_name(RugosityPattern pattern);

// σ per segment for n segments (m). `seed` is used by type_3 only. Throws
// std::invalid_argument for a negative or non-finite sigma or n == 0.
std::vector<double> pattern_sigmas(RugosityPattern pattern, double sigma, std::size_t n,
                                   std::uint64_t seed);

}  // namespace rugosim
