// The rugosim command line. For now: version and help; the subcommands of INTERFACE.md
// arrive with the scene, simulation and rendering layers.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "engine/core/version.h"

int main(int argc, char** argv) {
  CLI::App app{"rugosim: simulate and render 2D rigid bodies with rough B-spline boundaries",
               "rugosim"};
  app.set_version_flag("--version", std::string("rugosim ") + rugosim::kVersion);
  app.footer(
      "Exit codes: 0 success, 1 runtime failure, 2 bad usage or invalid scene, 130 interrupted.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 returns 0 for --help/--version; usage errors become exit code 2.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  fmt::print("{}", app.help());
  return 0;
}
