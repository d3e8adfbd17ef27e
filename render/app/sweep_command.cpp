// `rugosim sweep SPEC`: --list, --task I|auto, --gather (commands.h, docs/sweeps.md).
#include <filesystem>
#include <stdexcept>

#include <fmt/core.h>

#include "render/app/commands.h"
#include "render/app/scene_input.h"
#include "render/app/sweep_gather.h"
#include "render/app/sweep_spec.h"
#include "render/app/sweep_task.h"
#include "render/app/task_index.h"

namespace rugosim::app {
namespace {

// SPEC without ".json", plus ".sweep": beside the spec, so that every task of an array finds
// the same folder whatever its working directory.
std::string default_folder(const std::string& spec_path) {
  std::filesystem::path path(spec_path);
  if (path.extension() == ".json") path.replace_extension();
  return path.string() + ".sweep";
}

int list_tasks(const SweepSpec& spec, const std::string& dir) {
  std::size_t done = 0;
  fmt::print("task");
  for (const SweepAxis& axis : spec.axes)
    fmt::print("\t{}", axis.name);
  fmt::print("\tstate\n");
  for (std::size_t task = 0; task < spec.task_count(); ++task) {
    fmt::print("{}", task);
    const std::vector<std::size_t> index = spec.coordinates(task);
    for (std::size_t a = 0; a < spec.axes.size(); ++a)
      fmt::print("\t{}", spec.axes[a].values[index[a]].dump());
    const std::optional<nlohmann::json> result = read_task_result(dir, task);
    const bool complete = result && result_of(*result, spec);
    done += complete ? 1 : 0;
    fmt::print("\t{}\n", complete ? "done" : "to do");
  }
  fmt::print(stderr,
             "{}: {} tasks, {} done, in {}\n"
             "run one: rugosim sweep {} --task I (0-based), or --task auto as a Slurm array task "
             "(--array=0-{}), a Kubernetes Indexed Job or under GNU parallel\n",
             spec.file, spec.task_count(), done, dir, spec.file, spec.task_count() - 1);
  return kExitOk;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  SweepSpecLoad load = load_sweep_spec(o.spec_path);
  if (!load.errors.empty()) {
    for (const SceneError& e : load.errors)
      fmt::print(stderr, "error: {}\n", e.describe());
    return kExitUsage;
  }
  const SweepSpec& spec = load.spec;
  const std::string dir = o.output_dir.empty() ? default_folder(o.spec_path) : o.output_dir;
  try {
    if (o.list) return list_tasks(spec, dir);
    if (o.gather) return gather_sweep(spec, dir, o.plot_format);
    if (o.task.empty()) {
      fmt::print(stderr, "error: sweep: give one of --list, --task I|auto and --gather\n");
      return kExitUsage;
    }
    std::size_t task = 0;
    try {
      if (o.task == "auto") {
        task = task_index_from_environment("--task auto");
      } else {
        const std::optional<std::size_t> n = whole_number(o.task);
        if (!n)
          throw std::invalid_argument(
              fmt::format("--task: expected a whole number or auto, got \"{}\"", o.task));
        task = *n;
      }
      if (task >= spec.task_count()) {
        throw std::invalid_argument(fmt::format("--task {}: the sweep has {} tasks (0 to {})", task,
                                                spec.task_count(), spec.task_count() - 1));
      }
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return kExitUsage;
    }
    return run_sweep_task(spec, dir, task, o.threads, o.overwrite);
  } catch (const std::exception& e) {
    // An output that cannot be written or read back (a full disk, a damaged task file).
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
