// Rough detail as a function of arc length along a closed boundary: a sum of octaves, each a
// periodic uniform cubic B-spline through independent N(0, 1) values on a lattice (the paper's
// model of detail, §2.2: control points displaced by normal noise, the curve through them),
// the coarsest with lattice spacing ℓ (the correlation length), each next one half as wide and
// 2^−H as strong (H the Hurst exponent: self-affine, like rock, not a single-scale sawtooth).
//
// The octaves' strengths are normalised over the unending series (ℓ, ℓ/2, ℓ/4, …) so that the
// whole fractal has variance 1/2, averaged along the boundary: σ·noise(s) moves the boundary by
// σ/√2 RMS, the statistic of the paper's model at its own scale. Octaves too fine to be seen are
// left out when the noise is made, but leaving one out never changes another: octave k's lattice
// comes from its own seeded stream and its strength from the whole series, so the detail has the
// same shape at every resolution and is only sampled more finely when there are more pixels.
#pragma once

#include <cstdint>
#include <vector>

namespace rugosim {

struct BoundaryNoiseSpec {
  double period = 0.0;              // m, the boundary's length
  double correlation_length = 0.0;  // m, ℓ: lattice spacing of the coarsest octave
  int octaves = 12;                 // ℓ, ℓ/2, … ℓ/2048 at most
  double hurst = 0.8;               // octave k's strength ∝ 2^(−H·k)
  double clamp_sigmas = 3.0;        // lattice values are clamped at ±3 (no rare spikes)
};

class BoundaryNoise {
 public:
  // Octaves whose lattice spacing would be below `finest_spacing` (m) are left out, and so
  // are those that would need more than `max_lattice` values. Throws std::invalid_argument
  // for a period or correlation length that is not positive and finite.
  BoundaryNoise(const BoundaryNoiseSpec& spec, std::uint64_t seed, double finest_spacing,
                std::size_t max_lattice = std::size_t{1} << 20);

  // The noise at arc length s (any real; period `spec.period`), dimensionless.
  double operator()(double s) const;
  int octaves_drawn() const { return static_cast<int>(octaves_.size()); }
  // The lattice spacing of the finest octave drawn (m); the period when none is.
  double finest_spacing() const;

  // ∫₀¹ Σ B_i(t)² dt of the uniform cubic B-spline basis: the mean variance of a B-spline
  // through independent unit values (1/2 at the knots, 23/48·… between them).
  static constexpr double kMeanBasisSquare = 151.0 / 315.0;

 private:
  struct Octave {
    std::vector<double> values;  // the periodic lattice
    double strength = 0.0;
  };
  double period_;
  std::vector<Octave> octaves_;
};

}  // namespace rugosim
