// Running gnuplot (http://www.gnuplot.info, Debian package gnuplot-nox) on a script built in
// memory: the script goes through a pipe to its standard input, data included as datablocks, so
// no temporary script or data files are needed; the plot it writes to its standard output goes
// into a file. gnuplot's own messages are collected and reported, not interleaved with ours.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace rugosim::app {

// gnuplot could not be started, or it failed; what() says which, with gnuplot's messages.
class GnuplotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `gnuplot -d` (default settings: no user's ~/.gnuplot changes the result) from PATH with
// `script` on its standard input and its standard output written to `output_path` (created or
// truncated; the caller writes it under a temporary name and renames it when all went well).
// Returns what gnuplot printed on its standard error (warnings), empty when nothing. Throws
// GnuplotError when gnuplot is not found, is killed, exits with a non-zero status or writes
// nothing; output_path may then hold a partial file, which the caller removes.
std::string run_gnuplot(std::string_view script, const std::string& output_path);

// `text` as a gnuplot single-quoted string: quotes doubled, line breaks and other control
// characters (which would end the command) replaced by spaces. Backslashes stay as they are.
std::string gnuplot_quote(std::string_view text);

}  // namespace rugosim::app
