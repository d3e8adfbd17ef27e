// The rugosim program: parses the command line (command_line.h) and runs the chosen command.
#include <string>

#include <fmt/core.h>

#include "engine/core/thread_pool.h"
#include "render/app/command_line.h"
#include "render/app/commands.h"
#include "render/app/scene_input.h"

int main(int argc, char** argv) {
  using namespace rugosim::app;
  const std::unique_ptr<CommandLine> command_line = make_command_line(rugosim::available_cpus());
  CommandLine& c = *command_line;
  // A misspelt command: CLI11 would only say that the word was not expected.
  const std::string unknown = argc > 1 ? unknown_command_error(c, argv[1]) : std::string();
  if (!unknown.empty()) {
    fmt::print(stderr, "error: {}\nRun with --help for more information.\n", unknown);
    return kExitUsage;
  }
  try {
    c.app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 returns 0 for --help/--version; usage errors become exit code 2.
    const int code = c.app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  finish_parse(c);
  if (c.validate->parsed()) return run_validate(c.scene);
  if (c.info->parsed()) return run_info(c.scene, c.json);
  if (c.simulate->parsed()) return run_simulate(c.sim);
  if (c.render->parsed()) return run_render(c.render_options);
  if (c.snapshot->parsed()) return run_snapshot(c.snap);
  if (c.plot->parsed()) return run_plot(c.plot_options);
  if (c.join->parsed()) return run_join(c.join_options);
  if (c.plan_render->parsed()) return run_plan_render(c.plan_options);
  if (c.sweep->parsed()) return run_sweep(c.sweep_options);
  fmt::print("{}", c.app.help());
  return kExitOk;
}
