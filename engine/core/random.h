// Deterministic random numbers: the same seed gives the same sequence on every platform
// and standard library (std::normal_distribution and friends do not promise that).
// Generator: xoshiro256** (Blackman & Vigna), seeded through SplitMix64.
#pragma once

#include <array>
#include <cstdint>

namespace rugosim {

// One SplitMix64 step: advances state and returns a well-mixed 64-bit value.
std::uint64_t splitmix64(std::uint64_t& state);

// Combines a seed with a stream index (a body, a segment, a purpose) into an independent seed.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream);

class Rng {
 public:
  explicit Rng(std::uint64_t seed);

  std::uint64_t next_u64();
  // Uniform in [0, 1), 53 random bits.
  double uniform();
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal N(0, 1), by the Box-Muller transform.
  double normal();

 private:
  std::array<std::uint64_t, 4> s_{};
  double spare_normal_ = 0.0;
  bool has_spare_normal_ = false;
};

}  // namespace rugosim
