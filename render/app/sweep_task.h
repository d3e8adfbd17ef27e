// Where a sweep's tasks keep their results (docs/sweeps.md): DIR/task_NNNNNN/ holds the task's
// scene.json, its outputs and result.json (the sweep's hash, the axes' values, the measures). A
// task is written in DIR/.task_NNNNNN.partial-HOST-PID and renamed when complete, so a folder
// task_NNNNNN is always a whole result, and a task killed half-way leaves only a .partial folder
// that the next run of that task removes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/app/sweep_spec.h"

namespace rugosim::app {

// "DIR/task_000042".
std::string task_folder(const std::string& dir, std::size_t task);

// The sweep's hash as written in result.json: 16 hex digits.
std::string sweep_hash_text(std::uint64_t hash);

// DIR/task_NNNNNN/result.json, parsed; nullopt when there is none or it cannot be read (a task
// not done).
std::optional<nlohmann::json> read_task_result(const std::string& dir, std::size_t task);

// Whether `result` belongs to this sweep (same spec and scene bytes).
bool result_of(const nlohmann::json& result, const SweepSpec& spec);

// Runs task `task` (sweep_command.cpp's --task): the exit code; prints what it did.
int run_sweep_task(const SweepSpec& spec, const std::string& dir, std::size_t task, int threads,
                   bool overwrite);

}  // namespace rugosim::app
