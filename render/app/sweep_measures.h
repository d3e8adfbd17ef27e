// A sweep task's measures (sweep_spec.h): its outputs (stats.json, trajectory.csv, events.csv in
// the task's folder) reduced to one number each, then the expression measures, which may use
// the axes and the measures before them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/app/sweep_spec.h"

namespace rugosim::app {

// One value per measure of `spec`, in order; nullopt where there is nothing to reduce (no event
// of the kind asked, no frame in the window) or an expression uses such a measure. Throws
// CsvError or std::runtime_error naming the file when an output is missing or damaged.
std::vector<std::optional<double>> compute_measures(const SweepSpec& spec, std::size_t task,
                                                    const std::string& folder);

// Which outputs the measures read: "stats", "trajectory", "events" (each at most once).
std::vector<std::string> outputs_needed(const SweepSpec& spec);

// values reduced by `how` (first, last, mean, min, max, delta = last − first, range = max − min,
// sum, count); nullopt for no values (but count and sum, which give 0).
std::optional<double> reduce_values(const std::vector<double>& values, const std::string& how);

}  // namespace rugosim::app
