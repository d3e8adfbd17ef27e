// The look shared by rugosim's gnuplot figures (`rugosim plot`, `rugosim sweep --gather`): the
// terminal of each format at its size, a clean sans-serif font, a light grid, colours that stay
// apart for colour-blind readers, titles, and data passed inline as datablocks.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rugosim::app {

// Where a figure goes: "png" (pngcairo), "svg" or "pdf" (pdfcairo), width × height in pixels
// (a PDF gets a hundredth of an inch per pixel, and its fonts the same proportion).
struct FigureFormat {
  std::string kind = "png";
  int width = 1000;
  int height = 600;
};

// The i-th of ten distinct hues (Tableau 10) as a gnuplot colour, e.g. '#1f77b4'; cycles.
std::string colour(std::size_t i);
// The same hue, mostly transparent (gnuplot's #AARRGGBB counts AA as transparency).
std::string light_colour(std::size_t i);

// A value for a datablock: shortest exact form; NaN (gnuplot skips the point) for a value that
// is not finite.
void append_value(std::string& out, double x);

// Settings shared by every figure: the terminal of the format at its size, in a clean
// sans-serif font (11 pt at 1000 px wide, in proportion), a light grid behind the data, an open
// frame.
std::string preamble(const FigureFormat& format);

// The figure's title and, under it in grey, what it was drawn from (file names are shown as
// they are, never read as enhanced-text markup).
void append_titles(std::string& script, std::string_view title, std::string_view subtitle);

// `$NAME << EOD` ... `EOD`: rows of whitespace-separated values, each ending in a newline.
void append_datablock(std::string& script, std::string_view name, const std::string& rows);

// A legend entry cut to fit beside the axes (at a UTF-8 character boundary, with "…").
std::string shortened(const std::string& text);

}  // namespace rugosim::app
