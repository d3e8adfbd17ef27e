// The subcommands of the rugosim program (INTERFACE.md, "Command line"). Each returns the
// process's exit code.
#pragma once

#include <optional>
#include <string>

namespace rugosim::app {

// Exit 0 and a summary, or 2 and every error found.
int run_validate(const std::string& scene_path);

// Per body: segments, area, mass, centroid, inertia, range of λ, tree depth; as a table or as
// JSON (`{"bodies": [...]}`).
int run_info(const std::string& scene_path, bool json);

struct SimulateOptions {
  std::string scene_path;
  std::optional<double> duration;  // s, overrides world.duration
  std::optional<double> fps;       // overrides render.fps: the trajectory's frame rate
  std::optional<std::string> accuracy;
  std::string trajectory_path;  // empty: not written
  std::string events_path;
  std::string stats_path;
};

// Simulates and writes the telemetry files atomically; exit 130 on SIGINT after writing what
// was simulated so far.
int run_simulate(const SimulateOptions& options);

}  // namespace rugosim::app
