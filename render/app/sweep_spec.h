// A parameter sweep (`rugosim sweep SPEC.json`; docs/sweeps.md): one scene, axes of values set
// into it through JSON pointers (directly or by arithmetic expressions of the axes' values), the
// command each task runs, and the measures each task's outputs are reduced to. The tasks are the
// axes' cartesian product, numbered from 0 with the last axis varying fastest, so that a task
// index (a Slurm array index, a Kubernetes completion index, GNU parallel's sequence number)
// names one deterministic run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/scene_error.h"

namespace rugosim::app {

struct SweepAxis {
  std::string name;
  std::vector<nlohmann::json> values;  // numbers, or any JSON values when only `pointer` uses them
  std::string pointer;                 // the value itself goes here; empty for none
  // Scene keys set from expressions of the axes' values: (JSON pointer, expression).
  std::vector<std::pair<std::string, std::string>> set;
  bool numeric() const;  // every value is a number (expressions may use the axis)
};

// What a task's outputs are reduced to: one number, or null when there is nothing to reduce
// (no event of that kind, no frame in the window).
struct SweepMeasure {
  enum class Source { kStats, kTrajectory, kEvents, kExpression };
  std::string name;
  Source source = Source::kStats;
  std::string key;     // kStats: a stats.json key
  std::string body;    // kTrajectory: the body; kEvents: only events of this body (empty: all)
  std::string column;  // kTrajectory, kEvents: the CSV column (trajectory also "speed")
  std::string reduce;  // first, last, mean, min, max, delta, range; events also sum, count
  std::string kind;    // kEvents: "collision", "contact" or empty for both
  std::optional<double> from, to;  // the time window, s (inclusive); none: the whole run
  std::string expression;          // kExpression: of the axes and the measures before it
};

// The command each task runs in its own folder.
struct SweepCommand {
  bool render = false;                // false: simulate
  std::optional<std::string> preset;  // --accuracy
  std::optional<double> duration;     // s
  std::optional<double> fps;
  std::vector<std::string> outputs;  // simulate: "trajectory", "events", "stats" kept
  std::string size;                  // render: "WxH"; empty: the scene's
  std::string format = "mp4";        // render: "mp4" (clip.mp4) or "png" (frames/f_%05d.png)
  int crf = 18;                      // render
};

struct SweepSpec {
  std::string file;        // the spec, as given
  std::string name;        // "name", or the file's stem
  std::string scene_path;  // resolved against the spec's folder
  nlohmann::json scene;    // the scene file's JSON (comments dropped)
  std::vector<std::pair<std::string, nlohmann::json>> set;  // fixed changes to every task
  std::vector<SweepAxis> axes;
  SweepCommand command;
  std::vector<SweepMeasure> measures;
  std::uint64_t hash = 0;  // of the spec's and the scene's bytes: which sweep a result belongs to

  std::size_t task_count() const;
  // The index into each axis's values of task `task` (< task_count()).
  std::vector<std::size_t> coordinates(std::size_t task) const;
  // "gain=100 angle=10" for messages and listings.
  std::string describe(std::size_t task) const;
};

struct SweepSpecLoad {
  SweepSpec spec;                  // complete only when errors is empty
  std::vector<SceneError> errors;  // every problem found: file, JSON path, expectation
};

// Reads and checks the spec at `path` and the scene it names: keys (with "did you mean"), axis
// names and values, pointers (their parent must exist in the scene), expressions (parsed, every
// name known), measures (bodies of the scene, columns, reductions), and the scenes of the first
// and last tasks against the scene format.
SweepSpecLoad load_sweep_spec(const std::string& path);

// Task `task`'s scene: the spec's fixed changes, then each axis's pointer and expressions.
// Throws std::runtime_error when an expression's value is not a finite number.
nlohmann::json task_scene(const SweepSpec& spec, std::size_t task);

// The numeric values of task `task`'s axes by name (expressions' variables).
std::vector<std::pair<std::string, double>> task_variables(const SweepSpec& spec, std::size_t task);

}  // namespace rugosim::app
