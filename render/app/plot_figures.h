// The gnuplot scripts of `rugosim plot`: the paper's figure 8 (the friction coefficient of each
// collision event over time) and figures 10 and 11 (the velocity of bodies over time), as PNG,
// SVG or PDF at a chosen size.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "render/app/csv_reader.h"
#include "render/app/plot_style.h"

namespace rugosim::app {

// The range of the finite values added.
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double x) {
    if (!std::isfinite(x)) return;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  bool empty() const { return !(lo <= hi); }
};

// Figure 8: μ of every event over time. The ten pairs of bodies with the most events each get
// a colour and a legend entry, in order of their counts; the others share grey, with one entry
// that says how many they are; micro-collisions are small light dots underneath.
std::string friction_script(const Events& events, const std::string& file, bool contacts,
                            std::optional<double> t_end, const FigureFormat& format);

// Figures 10 and 11: the speed |v| (top) and vx (bottom) of each chosen body over time, one
// colour per body in both panels.
std::string velocity_script(const Trajectory& trajectory, const std::vector<std::size_t>& bodies,
                            const std::string& file, double t_end, const FigureFormat& format);

}  // namespace rugosim::app
