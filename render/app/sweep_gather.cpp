#include "render/app/sweep_gather.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"
#include "render/app/atomic_file.h"
#include "render/app/gnuplot.h"
#include "render/app/scene_input.h"
#include "render/app/sweep_task.h"

namespace rugosim::app {
namespace {

// Series beyond this many are clutter: the other axis is then left out of the colours.
constexpr std::size_t kMostSeries = 10;

std::optional<double> measure_of(const nlohmann::json& result, const std::string& name) {
  const auto measures = result.find("measures");
  if (measures == result.end() || !measures->is_object()) return std::nullopt;
  const auto v = measures->find(name);
  if (v == measures->end() || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

double axis_value(const SweepSpec& spec, std::size_t task, std::size_t a) {
  return spec.axes[a].values[spec.coordinates(task)[a]].get<double>();
}

std::string axis_label(const SweepSpec& spec, std::size_t a, const nlohmann::json& value) {
  return spec.axes[a].name + " = " + value.dump();
}

// The numeric axis that colours the lines of a plot against axis `a`: the first other one with
// at most kMostSeries values; none (one series) otherwise.
std::optional<std::size_t> series_axis(const SweepSpec& spec, std::size_t a) {
  for (std::size_t b = 0; b < spec.axes.size(); ++b) {
    if (b != a && spec.axes[b].values.size() <= kMostSeries) return b;
  }
  return std::nullopt;
}

std::string subtitle(const SweepSpec& spec) {
  return fmt::format("sweep {}: {} tasks of {}", spec.name, spec.task_count(),
                     std::filesystem::path(spec.scene_path).filename().string());
}

// Half the gap to the nearest other value of each value (a map's cell half-width); a lone
// value gets half of itself, or 0.5.
std::map<double, double> half_widths(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::map<double, double> half;
  for (std::size_t i = 0; i < values.size(); ++i) {
    double gap = std::numeric_limits<double>::infinity();
    if (i > 0) gap = std::min(gap, values[i] - values[i - 1]);
    if (i + 1 < values.size()) gap = std::min(gap, values[i + 1] - values[i]);
    if (!std::isfinite(gap)) gap = values[i] != 0.0 ? std::abs(values[i]) : 1.0;
    half[values[i]] = gap / 2.0;
  }
  return half;
}

}  // namespace

std::string sweep_csv(const SweepSpec& spec, const std::vector<nlohmann::json>& results) {
  std::string csv = "task";
  for (const SweepAxis& axis : spec.axes)
    csv.append(",").append(axis.name);
  for (const SweepMeasure& measure : spec.measures)
    csv.append(",").append(measure.name);
  csv += '\n';
  for (std::size_t task = 0; task < results.size(); ++task) {
    csv += std::to_string(task);
    const std::vector<std::size_t> index = spec.coordinates(task);
    for (std::size_t a = 0; a < spec.axes.size(); ++a) {
      csv += ',';
      const nlohmann::json& v = spec.axes[a].values[index[a]];
      if (v.is_number_float())
        append_number(csv, v.get<double>());
      else if (v.is_string())
        append_csv_field(csv, v.get<std::string>());
      else
        append_csv_field(csv, v.dump());
    }
    for (const SweepMeasure& measure : spec.measures) {
      csv += ',';
      if (const auto value = measure_of(results[task], measure.name)) append_number(csv, *value);
    }
    csv += '\n';
  }
  return csv;
}

std::string sweep_line_script(const SweepSpec& spec, const std::vector<nlohmann::json>& results,
                              std::size_t m, std::size_t a, const FigureFormat& format) {
  const std::string& measure = spec.measures[m].name;
  const std::optional<std::size_t> by = series_axis(spec, a);
  const std::size_t series = by ? spec.axes[*by].values.size() : 1;
  std::vector<std::string> rows(series);
  for (std::size_t task = 0; task < results.size(); ++task) {
    const std::size_t s = by ? spec.coordinates(task)[*by] : 0;
    append_value(rows[s], axis_value(spec, task, a));
    rows[s] += ' ';
    append_value(rows[s], measure_of(results[task], measure).value_or(std::nan("")));
    rows[s] += '\n';
  }
  std::string script = preamble(format);
  append_titles(script, fmt::format("{} against {}", measure, spec.axes[a].name), subtitle(spec));
  for (std::size_t s = 0; s < series; ++s)
    append_datablock(script, fmt::format("$S{}", s), rows[s]);
  script.append("set tmargin at screen 0.88\nset bmargin at screen 0.11\n");
  script.append("set lmargin at screen 0.1\n");
  script.append(fmt::format("set rmargin at screen {}\n", by ? 0.78 : 0.96));
  script.append("set xlabel ").append(gnuplot_quote(spec.axes[a].name)).append(" noenhanced\n");
  script.append("set ylabel ").append(gnuplot_quote(measure)).append(" noenhanced\n");
  script.append(
      "set key at screen 0.79, screen 0.88 left top vertical Left reverse samplen 2 nobox "
      "noenhanced\n");
  // Lines join the points of one series in order of x: with one axis, or one series per value
  // of the only other axis. Otherwise a series holds several points per x: points only.
  const bool lines = spec.axes.size() == 1 || (by && spec.axes.size() == 2);
  script.append("plot ");
  for (std::size_t s = 0; s < series; ++s) {
    if (s > 0) script.append(", \\\n     ");
    const std::string title =
        by ? "title " + gnuplot_quote(shortened(axis_label(spec, *by, spec.axes[*by].values[s])))
           : std::string("notitle");
    script.append(
        fmt::format("$S{} using 1:2 with {} linecolor rgb {} pointtype 7 pointsize 0.8 {}", s,
                    lines ? "linespoints" : "points", colour(s), title));
  }
  script.append("\n");
  return script;
}

std::string sweep_map_script(const SweepSpec& spec, const std::vector<nlohmann::json>& results,
                             std::size_t m, std::size_t x, std::size_t y,
                             const FigureFormat& format) {
  const std::string& measure = spec.measures[m].name;
  // The mean over the other axes of each (x, y) cell.
  std::map<std::pair<double, double>, std::pair<double, std::size_t>> cells;
  std::vector<double> xs, ys;
  for (std::size_t task = 0; task < results.size(); ++task) {
    const double vx = axis_value(spec, task, x), vy = axis_value(spec, task, y);
    xs.push_back(vx);
    ys.push_back(vy);
    auto& cell = cells[{vx, vy}];
    if (const auto v = measure_of(results[task], measure)) {
      cell.first += *v;
      cell.second += 1;
    }
  }
  const std::map<double, double> hx = half_widths(xs), hy = half_widths(ys);
  std::string rows;
  for (const auto& [at, sum] : cells) {
    append_value(rows, at.first);
    rows += ' ';
    append_value(rows, at.second);
    rows += ' ';
    append_value(rows, hx.at(at.first));
    rows += ' ';
    append_value(rows, hy.at(at.second));
    rows += ' ';
    append_value(rows, sum.second > 0 ? sum.first / double(sum.second) : std::nan(""));
    rows += '\n';
  }
  std::string script = preamble(format);
  const bool mean = spec.axes.size() > 2;
  append_titles(script,
                fmt::format("{} over {} and {}{}", measure, spec.axes[x].name, spec.axes[y].name,
                            mean ? " (mean over the other axes)" : ""),
                subtitle(spec));
  append_datablock(script, "$M", rows);
  script.append("set tmargin at screen 0.88\nset bmargin at screen 0.11\n");
  script.append("set lmargin at screen 0.1\nset rmargin at screen 0.84\n");
  script.append("set xlabel ").append(gnuplot_quote(spec.axes[x].name)).append(" noenhanced\n");
  script.append("set ylabel ").append(gnuplot_quote(spec.axes[y].name)).append(" noenhanced\n");
  script.append("set cblabel ").append(gnuplot_quote(measure)).append(" noenhanced\n");
  script.append("unset grid\nset tics front\n");
  // viridis: perceptually uniform, readable in grey and by colour-blind readers.
  script.append(
      "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 "
      "'#fde725')\n");
  script.append(fmt::format(
      "set xrange [{}:{}]\nset yrange [{}:{}]\n", hx.begin()->first - hx.begin()->second,
      hx.rbegin()->first + hx.rbegin()->second, hy.begin()->first - hy.begin()->second,
      hy.rbegin()->first + hy.rbegin()->second));
  script.append(
      "plot $M using 1:2:3:4:5 with boxxyerror fillstyle solid 1.0 noborder palette notitle\n");
  return script;
}

int gather_sweep(const SweepSpec& spec, const std::string& dir, const std::string& format) {
  std::vector<nlohmann::json> results;
  std::vector<std::size_t> missing;
  for (std::size_t task = 0; task < spec.task_count(); ++task) {
    std::optional<nlohmann::json> result = read_task_result(dir, task);
    if (!result || !result_of(*result, spec)) {
      missing.push_back(task);
      continue;
    }
    results.push_back(std::move(*result));
  }
  if (!missing.empty()) {
    std::string list;
    for (std::size_t i = 0; i < missing.size() && i < 20; ++i)
      list += (i > 0 ? ", " : "") + std::to_string(missing[i]);
    if (missing.size() > 20) list += ", ...";
    fmt::print(stderr,
               "error: {} of {} tasks of {} have no result in {} yet: {} (run them with --task I; "
               "a task already done is skipped, so the whole array may be resubmitted); nothing "
               "written\n",
               missing.size(), spec.task_count(), spec.file, dir, list);
    return kExitFailure;
  }
  const std::string csv_path = dir + "/sweep.csv";
  write_text_atomically(csv_path, sweep_csv(spec, results));
  fmt::print("wrote {} ({} tasks)\n", csv_path, results.size());

  const FigureFormat figure{format, 1000, 600};
  std::vector<std::size_t> numeric;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (spec.axes[a].numeric() && spec.axes[a].values.size() > 1) numeric.push_back(a);
  }
  const std::string plots = dir + "/plots";
  std::filesystem::create_directories(plots);
  std::size_t written = 0;
  for (std::size_t m = 0; m < spec.measures.size(); ++m) {
    std::vector<std::pair<std::string, std::string>> figures;  // file, script
    for (const std::size_t a : numeric) {
      figures.emplace_back(
          fmt::format("{}/{}_vs_{}.{}", plots, spec.measures[m].name, spec.axes[a].name, format),
          sweep_line_script(spec, results, m, a, figure));
    }
    if (numeric.size() >= 2) {
      figures.emplace_back(fmt::format("{}/{}_map.{}", plots, spec.measures[m].name, format),
                           sweep_map_script(spec, results, m, numeric[0], numeric[1], figure));
    }
    for (const auto& [file, script] : figures) {
      RenamedFile out(file);
      try {
        const std::string warnings = run_gnuplot(script, out.temporary());
        if (!warnings.empty())
          fmt::print(stderr, "warning: gnuplot, drawing {}:\n{}\n", file, warnings);
        out.commit();
        ++written;
      } catch (const GnuplotError& e) {
        fmt::print(stderr, "error: drawing {}: {}\n", file, e.what());
        return kExitFailure;
      }
    }
  }
  fmt::print("wrote {} plot{} in {}\n", written, written == 1 ? "" : "s", plots);
  return kExitOk;
}

}  // namespace rugosim::app
