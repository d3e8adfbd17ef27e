// Helpers shared by the test suites: numbers for RecordProperty, and small builders.
#pragma once

#include <sstream>
#include <string>

#include "engine/dynamics/material.h"

namespace rugosim::testing {

// A number in scientific notation with `precision` digits after the point, for
// RecordProperty: measured figures show up in the test XML whatever their magnitude.
inline std::string scientific(double x, int precision = 3) {
  std::ostringstream out;
  out.precision(precision);
  out << std::scientific << x;
  return out.str();
}

// A material with the given restitutions and λ_min and the default density.
inline Material make_material(double restitution, double restitution_max, double lambda_min = 0.0) {
  Material m;
  m.restitution = restitution;
  m.restitution_max = restitution_max;
  m.lambda_min = lambda_min;
  return m;
}

}  // namespace rugosim::testing
