#include "render/app/plot_style.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"
#include "render/app/gnuplot.h"

namespace rugosim::app {
namespace {

// Distinct colours that stay apart for colour-blind readers (the Tableau 10 hues).
constexpr std::string_view kColours[] = {"1f77b4", "d62728", "2ca02c", "ff7f0e", "9467bd",
                                         "8c564b", "e377c2", "17becf", "7f7f7f", "bcbd22"};
constexpr std::size_t kColourCount = std::size(kColours);

}  // namespace

std::string colour(std::size_t i) {
  return fmt::format("'#{}'", kColours[i % kColourCount]);
}

std::string light_colour(std::size_t i) {
  return fmt::format("'#B0{}'", kColours[i % kColourCount]);
}

void append_value(std::string& out, double x) {
  if (std::isfinite(x)) {
    append_number(out, x);
  } else {
    out.append("NaN");
  }
}

std::string preamble(const FigureFormat& format) {
  const double font = 11.0 * std::min(format.width / 1000.0, format.height / 600.0 * 1.2);
  std::string terminal;
  if (format.kind == "svg") {
    terminal = fmt::format(
        "set terminal svg size {},{} dynamic enhanced font 'DejaVu Sans,{:.1f}' "
        "linewidth 1.2 background rgb 'white'\n",
        format.width, format.height, font);
  } else if (format.kind == "pdf") {
    // pdfcairo measures in inches: a hundredth per pixel, the font in the same proportion.
    terminal = fmt::format(
        "set terminal pdfcairo size {}in,{}in enhanced font 'DejaVu Sans,{:.1f}' "
        "linewidth 1.2 background rgb 'white'\n",
        format.width / 100.0, format.height / 100.0, font * 0.72);
  } else {
    terminal = fmt::format(
        "set terminal pngcairo size {},{} enhanced font 'DejaVu Sans,{:.1f}' "
        "linewidth 1.2 background rgb 'white'\n",
        format.width, format.height, font);
  }
  return "set encoding utf8\n" + terminal +
         "set border 3 linecolor rgb '#444444'\n"
         "set tics nomirror out\n"
         "set grid xtics ytics linetype 1 linecolor rgb '#e4e4e4' linewidth 1\n"
         "set grid back\n"
         "set title font ',14'\n";
}

void append_titles(std::string& script, std::string_view title, std::string_view subtitle) {
  script.append("set label 90 ").append(gnuplot_quote(title));
  script.append(" at screen 0.5, screen 0.965 center font ',14' noenhanced front\n");
  script.append("set label 91 ").append(gnuplot_quote(subtitle));
  script.append(
      " at screen 0.5, screen 0.925 center font ',10' textcolor rgb '#666666' noenhanced "
      "front\n");
}

void append_datablock(std::string& script, std::string_view name, const std::string& rows) {
  script.append(name).append(" << EOD\n").append(rows).append("EOD\n");
}

std::string shortened(const std::string& text) {
  constexpr std::size_t kLongest = 24;
  if (text.size() <= kLongest) return text;
  std::size_t cut = kLongest - 1;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
    --cut;  // UTF-8
  return text.substr(0, cut) + "…";
}

}  // namespace rugosim::app
