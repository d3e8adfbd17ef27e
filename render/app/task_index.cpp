#include "render/app/task_index.h"

#include <charconv>
#include <cstdlib>
#include <stdexcept>

#include <fmt/core.h>

namespace rugosim::app {

std::optional<std::size_t> whole_number(std::string_view text) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::size_t task_index_from_environment(std::string_view option) {
  struct Source {
    const char* variable;
    std::size_t base;
  };
  for (const Source& s : {Source{"SLURM_ARRAY_TASK_ID", 0}, Source{"JOB_COMPLETION_INDEX", 0},
                          Source{"PARALLEL_SEQ", 1}}) {
    const char* value = std::getenv(s.variable);
    if (value == nullptr) continue;
    const std::optional<std::size_t> n = whole_number(value);
    if (!n || *n < s.base) {
      throw std::invalid_argument(
          fmt::format("{}: {}=\"{}\" is not a task index (expected a whole number >= {})", option,
                      s.variable, value, s.base));
    }
    return *n - s.base;
  }
  throw std::invalid_argument(fmt::format(
      "{}: none of SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX and PARALLEL_SEQ is set (run it as "
      "a Slurm array task, a Kubernetes Indexed Job or under GNU parallel, or give the index)",
      option));
}

}  // namespace rugosim::app
