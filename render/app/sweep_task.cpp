#include "render/app/sweep_task.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"
#include "render/app/atomic_file.h"
#include "render/app/commands.h"
#include "render/app/csv_reader.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"
#include "render/app/sweep_expression.h"
#include "render/app/sweep_measures.h"
#include "render/app/task_index.h"

namespace rugosim::app {
namespace {

namespace fs = std::filesystem;

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  std::string text = name;
  for (char& c : text) {
    if (c == '-' || c == '/' || c == '.') c = '_';  // the folder name's separators
  }
  return text;
}

std::string partial_prefix(std::size_t task) {
  return fmt::format(".task_{:06}.partial-", task);
}

// Removes what earlier runs of this task on this machine left when they were killed (their
// process is gone); a run still going, or one on another machine, is left alone.
void remove_stale_partials(const std::string& dir, std::size_t task) {
  const std::string prefix = partial_prefix(task) + host_name() + "-";
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::optional<std::size_t> pid = whole_number(name.substr(prefix.size()));
    // Our own pid too: a folder of an earlier process that had it (a retried container whose
    // host name and pid repeat, as in a Kubernetes Indexed Job).
    const bool ours = pid && *pid == static_cast<std::size_t>(::getpid());
    if (!pid || ours || (::kill(static_cast<pid_t>(*pid), 0) != 0 && errno == ESRCH)) {
      fs::remove_all(entry.path(), error);
      fmt::print(stderr, "sweep: removed {}, left by a run of task {} that was stopped\n",
                 entry.path().string(), task);
    }
  }
}

extern "C" void on_sigterm(int) {
  ::raise(SIGINT);
}

// Removes the partial folder unless the task completed.
class PartialFolder {
 public:
  // Created afresh: a folder already there (which remove_stale_partials would have removed)
  // is never reused, so nothing of another run can slip into a result.
  explicit PartialFolder(std::string path) : path_(std::move(path)) {
    if (!fs::create_directory(path_))
      throw std::runtime_error(fmt::format("{} exists already", path_));
  }
  ~PartialFolder() {
    std::error_code error;
    if (!kept_) fs::remove_all(path_, error);
  }
  PartialFolder(const PartialFolder&) = delete;
  PartialFolder& operator=(const PartialFolder&) = delete;
  const std::string& path() const { return path_; }
  void keep() { kept_ = true; }

 private:
  std::string path_;
  bool kept_ = false;
};

// The task's command, in `folder`; its exit code.
int run_command(const SweepSpec& spec, const std::string& folder, int threads) {
  const SweepCommand& c = spec.command;
  AccuracyOverride accuracy;
  accuracy.preset = c.preset;
  const std::string scene = folder + "/scene.json";
  if (c.render) {
    RenderOptions o;
    o.scene_path = scene;
    if (c.format == "png") {
      fs::create_directories(folder + "/frames");
      o.output = folder + "/frames/f_%05d.png";
    } else {
      o.output = folder + "/clip.mp4";
    }
    o.size = c.size;
    o.fps = c.fps;
    o.duration = c.duration;
    o.accuracy = accuracy;
    o.threads = threads;
    o.crf = c.crf;
    o.overwrite = true;
    return run_render(o);
  }
  std::vector<std::string> outputs = c.outputs;
  for (const std::string& needed : outputs_needed(spec)) {
    if (std::find(outputs.begin(), outputs.end(), needed) == outputs.end())
      outputs.push_back(needed);
  }
  if (c.outputs.empty() && std::find(outputs.begin(), outputs.end(), "stats") == outputs.end())
    outputs.emplace_back("stats");  // what the run cost: always, unless the outputs are listed
  const auto wanted = [&](const char* name) {
    return std::find(outputs.begin(), outputs.end(), name) != outputs.end();
  };
  SimulateOptions o;
  o.scene_path = scene;
  o.duration = c.duration;
  o.fps = c.fps;
  o.accuracy = accuracy;
  o.threads = threads;
  if (wanted("trajectory")) o.trajectory_path = folder + "/trajectory.csv";
  if (wanted("events")) o.events_path = folder + "/events.csv";
  if (wanted("stats")) o.stats_path = folder + "/stats.json";
  return run_simulate(o);
}

}  // namespace

std::string task_folder(const std::string& dir, std::size_t task) {
  return fmt::format("{}/task_{:06}", dir, task);
}

std::string sweep_hash_text(std::uint64_t hash) {
  return fmt::format("{:016x}", hash);
}

std::optional<nlohmann::json> read_task_result(const std::string& dir, std::size_t task) {
  const std::optional<std::string> text = read_whole_file(task_folder(dir, task) + "/result.json");
  if (!text) return std::nullopt;
  try {
    nlohmann::json result = nlohmann::json::parse(*text);
    if (result.is_object()) return result;
  } catch (const nlohmann::json::exception&) {
  }
  return std::nullopt;
}

bool result_of(const nlohmann::json& result, const SweepSpec& spec) {
  return result.contains("sweep") && result["sweep"] == sweep_hash_text(spec.hash);
}

int run_sweep_task(const SweepSpec& spec, const std::string& dir, std::size_t task, int threads,
                   bool overwrite) {
  const std::string final_folder = task_folder(dir, task);
  const std::string what =
      fmt::format("task {} of {} ({})", task, spec.task_count(), spec.describe(task));
  if (fs::exists(final_folder)) {
    const std::optional<nlohmann::json> result = read_task_result(dir, task);
    if (result && result_of(*result, spec)) {
      fmt::print("{}: done already, in {}\n", what, final_folder);
      return kExitOk;
    }
    if (!overwrite) {
      fmt::print(stderr,
                 "error: {} holds {} (the spec or its scene changed since); remove it, or give -y "
                 "to run the task again\n",
                 final_folder, result ? "the result of another sweep" : "no complete result");
      return kExitUsage;
    }
    fs::remove_all(final_folder);
  }
  nlohmann::json scene;
  try {
    scene = task_scene(spec, task);
  } catch (const std::exception& e) {  // an expression without a value here, a JSON error
    fmt::print(stderr, "error: {}: {}: {}\n", spec.file, what, e.what());
    return kExitUsage;
  }
  fs::create_directories(dir);
  remove_stale_partials(dir, task);
  PartialFolder partial(
      fmt::format("{}/{}{}-{}", dir, partial_prefix(task), host_name(), ::getpid()));
  write_text_atomically(partial.path() + "/scene.json", scene.dump(2) + "\n");
  const auto start = std::chrono::steady_clock::now();
  // While the task runs, SIGTERM (Slurm's scancel, a time limit, a preemption; Kubernetes
  // stopping a pod) stops it as Ctrl-C does: the command stops within its step and returns 130,
  // and the partial folder is removed. Before the command has installed its SIGINT handler,
  // SIGINT ends the process as SIGTERM would have.
  const ScopedSignalHandler sigterm(SIGTERM, on_sigterm);
  const int code = run_command(spec, partial.path(), threads);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (code != kExitOk) {
    fmt::print(stderr, "sweep: {} stopped with exit code {}; nothing kept\n", what, code);
    return code;
  }
  const std::vector<std::optional<double>> values = compute_measures(spec, task, partial.path());
  nlohmann::json result = {{"sweep", sweep_hash_text(spec.hash)},
                           {"name", spec.name},
                           {"task", task},
                           {"wall_time", wall}};
  const std::vector<std::size_t> index = spec.coordinates(task);
  nlohmann::json axes = nlohmann::json::object();
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    axes[spec.axes[a].name] = spec.axes[a].values[index[a]];
  nlohmann::json measures = nlohmann::json::object();
  for (std::size_t m = 0; m < spec.measures.size(); ++m)
    measures[spec.measures[m].name] = values[m] ? nlohmann::json(*values[m]) : nlohmann::json();
  result["axes"] = axes;
  result["measures"] = measures;
  write_text_atomically(partial.path() + "/result.json", result.dump(2) + "\n");

  // Complete: the rename makes it visible at once. Another run of the same task may have won
  // the race (a resubmitted array task): then its result stands.
  std::error_code error;
  fs::rename(partial.path(), final_folder, error);
  if (error) {
    if (fs::exists(final_folder + "/result.json")) {
      fmt::print("{}: done meanwhile by another run, in {}\n", what, final_folder);
      return kExitOk;
    }
    fmt::print(stderr, "error: cannot rename {} to {}: {}\n", partial.path(), final_folder,
               error.message());
    return kExitFailure;
  }
  partial.keep();
  fmt::print("{}: done in {:.3g} s, in {}\n", what, wall, final_folder);
  return kExitOk;
}

}  // namespace rugosim::app
