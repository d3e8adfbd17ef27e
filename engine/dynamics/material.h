// What a body is made of: its areal density, how it bounces (paper §4.3: the restitution ε of a
// collision, and ε_max, the largest restitution of a resting-contact micro-collision, reached
// at the deepest penetration of the tolerance band) and below what tolerance it is frictionless
// (paper §4.2, eq. 5: μ = k·max(0, λ − λ_min)). Scene key `materials` (INTERFACE.md).
#pragma once

#include <cmath>
#include <sstream>
#include <string>

namespace rugosim {

struct Material {
  // A lamina of 1 m thickness of something as dense as water.
  static constexpr double kDefaultDensity = 1000.0;
  // Half the approach speed comes back: visibly bouncy, yet piles settle quickly.
  static constexpr double kDefaultRestitution = 0.5;
  // Equal to the default ε, so a material that sets nothing has a constant ε_c(δ) = ε.
  // A scene that sets only `restitution` above this must set `restitution_max` too.
  static constexpr double kDefaultRestitutionMax = 0.5;
  // Any roughness at all gives friction.
  static constexpr double kDefaultLambdaMin = 0.0;

  double density = kDefaultDensity;          // kg/m² (kg/m³ times the thickness), > 0
  double restitution = kDefaultRestitution;  // ε, dimensionless, in [0, 1]
  // ε_max, dimensionless, in [ε, 1]: above 1 a micro-collision would add kinetic energy.
  double restitution_max = kDefaultRestitutionMax;
  double lambda_min = kDefaultLambdaMin;  // m, >= 0: tolerances up to this are frictionless

  // Empty when the material is usable, else the first problem found, naming the key (as the
  // scene spells it) and the value, e.g. "restitution must be in [0, 1], got 1.5".
  std::string validate() const {
    std::ostringstream why;
    if (!(std::isfinite(density) && density > 0.0)) {
      why << "density must be finite and > 0 (kg/m²), got " << density;
    } else if (!(restitution >= 0.0 && restitution <= 1.0)) {
      why << "restitution must be in [0, 1], got " << restitution;
    } else if (!(restitution_max >= restitution && restitution_max <= 1.0)) {
      why << "restitution_max must be in [restitution, 1] = [" << restitution << ", 1], got "
          << restitution_max;
    } else if (!(std::isfinite(lambda_min) && lambda_min >= 0.0)) {
      why << "lambda_min must be finite and >= 0 (m), got " << lambda_min;
    }
    return why.str();
  }
};

}  // namespace rugosim
