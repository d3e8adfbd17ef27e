// The index of the task this process is, as the engine that started it says: a Slurm job array,
// a Kubernetes Indexed Job or GNU parallel (docs/scale-out.md). `render --chunk auto/N` and
// `sweep --task auto` read it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace rugosim::app {

// The first set of SLURM_ARRAY_TASK_ID (0-based, as submitted with --array=0-(N-1)),
// JOB_COMPLETION_INDEX (a Kubernetes Indexed Job, 0-based) and PARALLEL_SEQ (GNU parallel,
// 1-based: minus one), 0-based. Throws std::invalid_argument naming `option` (the option that
// asked, e.g. "--chunk auto") when none is set or the one set is not a whole number.
std::size_t task_index_from_environment(std::string_view option);

// A whole number written in decimal and nothing else; nullopt otherwise.
std::optional<std::size_t> whole_number(std::string_view text);

}  // namespace rugosim::app
