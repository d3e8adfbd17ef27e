#include "convergence_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <fmt/core.h>

#include "render/app/gnuplot.h"

namespace rugosim::study {
namespace {

// A Markdown table's header: the `lead` columns, one column per step, the `tail` columns.
std::string step_header(const std::vector<ConvergencePoint>& steps,
                        const std::vector<std::string>& lead,
                        const std::vector<std::string>& tail) {
  std::string head = "|", rule = "|";
  for (const std::string& name : lead)
    head += " " + name + " |";
  for (const ConvergencePoint& p : steps)
    head += fmt::format(" {:g} ms |", 1e3 * p.step);
  for (const std::string& name : tail)
    head += " " + name + " |";
  for (std::size_t i = 0; i < lead.size() + steps.size() + tail.size(); ++i)
    rule += "---|";
  return head + "\n" + rule + "\n";
}

}  // namespace

void write_convergence_csv(const std::filesystem::path& path,
                           const std::vector<SceneConvergence>& scenes) {
  std::ofstream out(path);
  out << "scene,max_step,wall_s,error_vs_limit,distance_from_twice_the_step,closed_form_error,"
         "steps,bisections,fallbacks,crossings,richardson_order,observed_order\n";
  for (const SceneConvergence& s : scenes) {
    for (const ConvergencePoint& p : s.points) {
      out << fmt::format("{},{:g},{:.6g},{:.6g},{:.6g},{},{},{},{},{},{:.3g},{:.3g}\n", s.name,
                         p.step, p.wall_s, p.error, p.previous,
                         p.closed ? fmt::format("{:.6g}", p.closed->error) : std::string(),
                         p.stats.steps, p.stats.bisections, p.stats.fallbacks, p.stats.crossings,
                         s.richardson_order, s.order);
    }
  }
}

void write_convergence_markdown(const std::filesystem::path& path,
                                const std::vector<SceneConvergence>& scenes) {
  if (scenes.empty()) return;
  std::ofstream out(path);
  const std::vector<ConvergencePoint>& first = scenes.front().points;
  out << fmt::format(
      "# Convergence with the step\n\n"
      "Written by `build/release/bench/accuracy_study docs/accuracy` (bench/convergence.cpp). "
      "Each non-chaotic scene run at max_step {:g} ms down to {:g} ms, halving, with every other "
      "knob at its finest (the figure scenes' reference settings). The method's limit is the "
      "Richardson extrapolation of the three finest runs, element by element, with the order "
      "they show themselves (p, kept within [0.5, 4]); each run's error is its RMS distance "
      "from that limit over every frame and body, positions and angles in body radii. "
      "\"Monotone\" allows an error {:.0f}% above the coarser step's (noise), and errors below "
      "{:g} body radii are below the solvers' own tolerances (\"converged\": no order to fit; "
      "bench/convergence.h says why); the observed order "
      "is the least-squares slope of log error against log step from {:g} to {:g} ms. For the "
      "validation scenes, the floor is the limit's own error against the closed form (the "
      "model's, which no step removes). Plot: `convergence.png`.\n\n",
      1e3 * first.front().step, 1e3 * first.back().step, 100 * kMonotoneTolerance, kNoiseFloor,
      1e3 * kOrderFrom, 1e3 * kOrderTo);
  out << step_header(first, {"scene"}, {"p", "order", "monotone", "floor"});
  for (const SceneConvergence& s : scenes) {
    out << "| " << s.name << " |";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const bool rise =
          i > 0 &&
          !decreases_monotonically({s.points[i - 1].error, s.points[i].error}, kMonotoneTolerance);
      out << fmt::format(" {:.2e}{} |", s.points[i].error, rise ? " ↑" : "");
    }
    out << fmt::format(
        " {:.2f} | {} | {} | {} |\n", s.richardson_order,
        std::isnan(s.order) ? std::string("converged") : fmt::format("{:.2f}", s.order),
        s.monotone
            ? "yes"
            : fmt::format("no (from {:g} ms)",
                          1e3 * s.points[static_cast<std::size_t>(std::max(s.first_rise, 0))].step),
        s.floor ? fmt::format("{:.2e}", s.floor->error) : std::string("—"));
  }
  out << "\n↑: a rise of more than the tolerance over the coarser step.\n\n"
         "Wall time of the simulation alone, ms:\n\n"
      << step_header(first, {"scene"}, {});
  for (const SceneConvergence& s : scenes) {
    out << "| " << s.name << " |";
    for (const ConvergencePoint& p : s.points)
      out << fmt::format(" {:.3g} |", 1e3 * p.wall_s);
    out << "\n";
  }
  bool any_closed = false;
  for (const SceneConvergence& s : scenes)
    any_closed = any_closed || s.floor.has_value();
  if (!any_closed) return;
  out << "\nThe closed forms along the step (each run's relative error), and the limit's:\n\n"
      << step_header(first, {"scene", "quantity"}, {"limit"});
  for (const SceneConvergence& s : scenes) {
    if (!s.floor) continue;
    for (std::size_t q = 0; q < s.floor->parts.size(); ++q) {
      out << "| " << s.name << " | " << s.floor->parts[q].first << " |";
      for (const ConvergencePoint& p : s.points)
        out << fmt::format(" {:.2e} |", p.closed->parts[q].second);
      out << fmt::format(" {:.2e} |\n", s.floor->parts[q].second);
    }
  }
}

void write_convergence_plot(const std::filesystem::path& path,
                            const std::vector<SceneConvergence>& scenes) {
  std::string data = "$conv << EOD\n";
  for (const SceneConvergence& s : scenes) {
    data += fmt::format("# {}\n", s.name);
    for (const ConvergencePoint& p : s.points) {
      // The finest run sits on the limit's Richardson line by construction; it is drawn too.
      data +=
          fmt::format("{:.6g} {:.6g} {:.6g}\n", 1e3 * p.step, p.wall_s, std::max(p.error, 1e-9));
    }
    data += "\n\n";
  }
  data += "EOD\n";
  std::string script = "set terminal pngcairo size 1400,600 font 'Sans,10' noenhanced\n" + data;
  script += "array names[" + std::to_string(scenes.size()) + "] = [";
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    script += fmt::format("{}{}", i == 0 ? "" : ", ", app::gnuplot_quote(scenes[i].name));
  }
  script += "]\n";
  script += fmt::format("NOISE = {:g}\n", kNoiseFloor);
  script += fmt::format(R"(N = {}
set multiplot layout 1,2
set logscale xy
set grid
set key bottom right font 'Sans,8'
set title 'error against the method''s limit, by step'
set xlabel 'max_step (ms)'
set ylabel 'RMS distance from the limit (body radii)'
set xrange [0.05:10]
set yrange [1e-9:0.1]
plot for [i=0:N-1] $conv index i using 1:3 with linespoints lw 1.5 dt i/6+1 pt i%6+4 ps 0.8 title names[i+1], \
     [0.0625:8] 1e-3*x with lines dt 2 lc rgb '#888888' title 'order 1', \
     [0.0625:8] NOISE with lines dt 3 lc rgb '#bbbbbb' title 'noise floor (below: plotted at 1e-9)'
set title 'error against the method''s limit, by wall time'
set xlabel 'wall time of the simulation (s)'
set key off
set autoscale x
plot for [i=0:N-1] $conv index i using 2:3 with linespoints lw 1.5 dt i/6+1 pt i%6+4 ps 0.8 title names[i+1]
unset multiplot
)",
                        scenes.size());
  app::run_gnuplot(script, path.string());
}

}  // namespace rugosim::study
