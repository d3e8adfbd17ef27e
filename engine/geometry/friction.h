// Friction from rugosity (paper §4.2, eq. 5): μ(λ) = k·max(0, λ − λ_min). Below the
// threshold λ_min a surface is frictionless. The paper's k = 1 is in its own length units;
// here k is the world's `friction_gain` (1/m) so that μ is dimensionless.
#pragma once

#include <algorithm>

namespace rugosim {

// λ and λ_min in m, gain in 1/m; returns a dimensionless coefficient.
inline double friction_coefficient(double lambda, double lambda_min, double gain) {
  return gain * std::max(0.0, lambda - lambda_min);
}

// Two boundaries in contact use the rougher one's coefficient (§4.2): μ = max(μ_a, μ_b).
inline double contact_friction(double mu_a, double mu_b) {
  return std::max(mu_a, mu_b);
}

}  // namespace rugosim
