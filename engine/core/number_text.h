// A number as messages show it: the shortest of fixed and scientific with `digits`
// significant digits, as printf's %g writes it (0.001, 1e-09, 200).
#pragma once

#include <sstream>
#include <string>

namespace rugosim {

inline std::string number_text(double x, int digits = 6) {
  std::ostringstream out;
  out.precision(digits);
  out << x;
  return out.str();
}

}  // namespace rugosim
