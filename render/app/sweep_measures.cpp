#include "render/app/sweep_measures.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "render/app/atomic_file.h"
#include "render/app/csv_reader.h"
#include "render/app/sweep_expression.h"

namespace rugosim::app {
namespace {

// Frame and event times are written with their exact shortest form, but a window's ends are
// typed by people (1 s) while frame times are sums of 1/fps: a nanosecond of slack.
constexpr double kWindowSlack = 1e-9;

bool in_window(const SweepMeasure& m, double time) {
  return (!m.from || time >= *m.from - kWindowSlack) && (!m.to || time <= *m.to + kWindowSlack);
}

double trajectory_column(const TrajectoryRow& row, const std::string& column) {
  if (column == "x") return row.x;
  if (column == "y") return row.y;
  if (column == "angle") return row.angle;
  if (column == "vx") return row.vx;
  if (column == "vy") return row.vy;
  if (column == "omega") return row.omega;
  if (column == "kinetic_energy") return row.kinetic_energy;
  return std::hypot(row.vx, row.vy);  // "speed"
}

double event_column(const EventRow& row, const std::string& column) {
  if (column == "time") return row.time;
  if (column == "t_a") return row.t_a;
  if (column == "t_b") return row.t_b;
  if (column == "x") return row.x;
  if (column == "y") return row.y;
  if (column == "nx") return row.nx;
  if (column == "ny") return row.ny;
  if (column == "lambda_a") return row.lambda_a;
  if (column == "lambda_b") return row.lambda_b;
  if (column == "mu") return row.mu;
  if (column == "vn") return row.vn;
  if (column == "vt") return row.vt;
  if (column == "jn") return row.jn;
  return row.jt;  // "jt"
}

nlohmann::json read_stats(const std::string& path) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) throw std::runtime_error(fmt::format("{}: cannot read the task's stats", path));
  try {
    return nlohmann::json::parse(*text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: not JSON ({})", path, e.what()));
  }
}

}  // namespace

std::optional<double> reduce_values(const std::vector<double>& values, const std::string& how) {
  if (how == "count") return static_cast<double>(values.size());
  if (how == "sum") return std::accumulate(values.begin(), values.end(), 0.0);
  if (values.empty()) return std::nullopt;
  if (how == "first") return values.front();
  if (how == "last") return values.back();
  if (how == "mean")
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (how == "min") return *lo;
  if (how == "max") return *hi;
  if (how == "range") return *hi - *lo;
  return values.back() - values.front();  // "delta"
}

std::vector<std::string> outputs_needed(const SweepSpec& spec) {
  std::vector<std::string> needed;
  const auto need = [&](const char* name) {
    if (std::find(needed.begin(), needed.end(), name) == needed.end()) needed.emplace_back(name);
  };
  for (const SweepMeasure& m : spec.measures) {
    if (m.source == SweepMeasure::Source::kStats) need("stats");
    if (m.source == SweepMeasure::Source::kTrajectory) need("trajectory");
    if (m.source == SweepMeasure::Source::kEvents) need("events");
  }
  return needed;
}

std::vector<std::optional<double>> compute_measures(const SweepSpec& spec, std::size_t task,
                                                    const std::string& folder) {
  const std::vector<std::string> needed = outputs_needed(spec);
  const auto needs = [&](const char* name) {
    return std::find(needed.begin(), needed.end(), name) != needed.end();
  };
  const nlohmann::json stats =
      needs("stats") ? read_stats(folder + "/stats.json") : nlohmann::json();
  const Trajectory trajectory =
      needs("trajectory") ? read_trajectory_csv(folder + "/trajectory.csv") : Trajectory{};
  const Events events = needs("events") ? read_events_csv(folder + "/events.csv") : Events{};

  std::vector<std::pair<std::string, double>> variables = task_variables(spec, task);
  std::vector<std::optional<double>> values;
  std::vector<std::string> nulls;  // measures without a value: expressions of them have none
  for (const SweepMeasure& m : spec.measures) {
    std::optional<double> value;
    std::vector<double> series;
    switch (m.source) {
      case SweepMeasure::Source::kStats:
        if (stats.contains(m.key) && stats[m.key].is_number()) value = stats[m.key].get<double>();
        break;
      case SweepMeasure::Source::kTrajectory: {
        const auto body = std::find(trajectory.bodies.begin(), trajectory.bodies.end(), m.body);
        const auto index = static_cast<std::size_t>(body - trajectory.bodies.begin());
        for (const TrajectoryRow& row : trajectory.rows) {
          if (row.body == index && in_window(m, row.time))
            series.push_back(trajectory_column(row, m.column));
        }
        value = reduce_values(series, m.reduce);
        break;
      }
      case SweepMeasure::Source::kEvents: {
        const auto body = std::find(events.bodies.begin(), events.bodies.end(), m.body);
        const auto index = static_cast<std::size_t>(body - events.bodies.begin());
        for (const EventRow& row : events.rows) {
          const bool kind =
              m.kind.empty() || (m.kind == "collision") == (row.kind == EventKind::kCollision);
          const bool of_body = m.body.empty() || row.body_a == index || row.body_b == index;
          if (kind && of_body && in_window(m, row.time))
            series.push_back(m.column.empty() ? 0.0 : event_column(row, m.column));
        }
        value = reduce_values(series, m.reduce);
        break;
      }
      case SweepMeasure::Source::kExpression: {
        const std::vector<std::string> used = expression_uses(m.expression, variables);
        const bool computable = std::none_of(used.begin(), used.end(), [&](const std::string& n) {
          return std::find(nulls.begin(), nulls.end(), n) != nulls.end();
        });
        try {
          if (computable) value = evaluate_expression(m.expression, variables);
        } catch (const ExpressionError&) {
          // No finite value here (1/0, sqrt of a negative): null, like a measure with no data.
        }
        break;
      }
    }
    if (value && !std::isfinite(*value)) value.reset();
    if (!value) nulls.push_back(m.name);
    variables.emplace_back(m.name, value.value_or(0.0));
    values.push_back(value);
  }
  return values;
}

}  // namespace rugosim::app
