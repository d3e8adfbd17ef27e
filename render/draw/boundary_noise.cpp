#include "render/draw/boundary_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/random.h"

namespace rugosim {
namespace {

bool positive(double x) {
  return std::isfinite(x) && x > 0.0;
}

}  // namespace

BoundaryNoise::BoundaryNoise(const BoundaryNoiseSpec& spec, std::uint64_t seed,
                             double finest_spacing, std::size_t max_lattice)
    : period_(spec.period) {
  if (!positive(spec.period) || !positive(spec.correlation_length)) {
    throw std::invalid_argument("boundary noise: the period and ℓ must be positive");
  }
  // Σ over every octave of its relative strength squared, the whole geometric series: the
  // variance is that of the unending fractal, whatever the number of octaves drawn.
  const double total = 1.0 / (1.0 - std::exp2(-2.0 * spec.hurst));
  // Variance 1/2 on average: each octave's B-spline has mean variance kMeanBasisSquare.
  const double gain = std::sqrt(0.5 / (kMeanBasisSquare * total));
  for (int k = 0; k < spec.octaves; ++k) {
    // A whole number of lattice cells round the boundary, at least four (one B-spline span).
    const double cells = std::round(spec.period / std::ldexp(spec.correlation_length, -k));
    const auto m = static_cast<std::size_t>(std::max(4.0, std::min(cells, 1e18)));
    if (spec.period / static_cast<double>(m) < finest_spacing || m > max_lattice) break;
    Octave octave;
    octave.strength = gain * std::exp2(-spec.hurst * k);
    Rng rng(derive_seed(seed, static_cast<std::uint64_t>(k)));
    octave.values.resize(m);
    for (double& v : octave.values)
      v = std::clamp(rng.normal(), -spec.clamp_sigmas, spec.clamp_sigmas);
    octaves_.push_back(std::move(octave));
  }
}

double BoundaryNoise::operator()(double s) const {
  double sum = 0.0;
  const double turns = s / period_;
  for (const Octave& octave : octaves_) {
    const std::size_t m = octave.values.size();
    const double x = (turns - std::floor(turns)) * static_cast<double>(m);
    const double cell = std::floor(x);
    const double t = x - cell;
    const auto i = static_cast<std::size_t>(cell) % m;
    const std::vector<double>& v = octave.values;
    // The uniform cubic B-spline basis at t, over values i−1 … i+2.
    const double u = 1.0 - t;
    const double b0 = u * u * u / 6.0;
    const double b1 = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0;
    const double b2 = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
    const double b3 = t * t * t / 6.0;
    sum += octave.strength *
           (b0 * v[(i + m - 1) % m] + b1 * v[i] + b2 * v[(i + 1) % m] + b3 * v[(i + 2) % m]);
  }
  return sum;
}

double BoundaryNoise::finest_spacing() const {
  return octaves_.empty() ? period_ : period_ / static_cast<double>(octaves_.back().values.size());
}

}  // namespace rugosim
