// `rugosim sweep SPEC --gather`: every task's result.json (sweep_task.h) into one table,
// DIR/sweep.csv, and figures of each measure: against each numeric axis (one line per value of
// another axis), and for two or more numeric axes a map over the first two.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/app/plot_style.h"
#include "render/app/sweep_spec.h"

namespace rugosim::app {

// The CSV: `task`, the axes, the measures (empty where a measure is null); one row per task in
// order. `results[i]` is task i's result.json.
std::string sweep_csv(const SweepSpec& spec, const std::vector<nlohmann::json>& results);

// gnuplot scripts (gnuplot.h) of measure `m` against axis `a`, and of `m` over the axes `x`
// and `y` as a map of coloured cells (the mean over other axes where there are more).
std::string sweep_line_script(const SweepSpec& spec, const std::vector<nlohmann::json>& results,
                              std::size_t m, std::size_t a, const FigureFormat& format);
std::string sweep_map_script(const SweepSpec& spec, const std::vector<nlohmann::json>& results,
                             std::size_t m, std::size_t x, std::size_t y,
                             const FigureFormat& format);

// Reads every task's result, writes DIR/sweep.csv and DIR/plots/*.<format>; the exit code. With
// a task not done, writes nothing and exits 1 naming the missing tasks.
int gather_sweep(const SweepSpec& spec, const std::string& dir, const std::string& format);

}  // namespace rugosim::app
