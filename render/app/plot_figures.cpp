#include "render/app/plot_figures.h"

#include <string_view>
#include <utility>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"
#include "render/app/gnuplot.h"

namespace rugosim::app {
namespace {

// Beyond these, one series or legend entry per pair or body is clutter, not information: the
// pairs past the ten with the most events share grey.
constexpr std::size_t kMostPairSeries = 10;
constexpr std::size_t kMostBodyLegend = 12;
constexpr const char* kOtherPairs = "'#9a9a9a'";
constexpr const char* kOtherPairsLight = "'#B09a9a9a'";

std::string pair_label(const Events& events, std::size_t a, std::size_t b) {
  return fmt::format("{} – {}", events.bodies[a], events.bodies[b]);
}

}  // namespace

std::string friction_script(const Events& events, const std::string& file, bool contacts,
                            std::optional<double> t_end, const FigureFormat& format) {
  // Pairs in order of first appearance, whichever body the file names first.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::size_t> pair_of(events.rows.size());
  std::size_t collision_count = 0, contact_count = 0;
  Range mu, time;
  for (std::size_t i = 0; i < events.rows.size(); ++i) {
    const EventRow& e = events.rows[i];
    const bool collision = e.kind == EventKind::kCollision;
    if (!collision && !contacts) continue;
    (collision ? collision_count : contact_count) += 1;
    mu.add(e.mu);
    time.add(e.time);
    const auto it = std::find_if(pairs.begin(), pairs.end(), [&](const auto& p) {
      return (p.first == e.body_a && p.second == e.body_b) ||
             (p.first == e.body_b && p.second == e.body_a);
    });
    pair_of[i] = static_cast<std::size_t>(it - pairs.begin());
    if (it == pairs.end()) pairs.emplace_back(e.body_a, e.body_b);
  }
  // The pairs by their number of events, most first (ties: first seen first); the first
  // kMostPairSeries are series of their own, the rest one grey series after them.
  std::vector<std::size_t> count(pairs.size(), 0);
  for (std::size_t i = 0; i < events.rows.size(); ++i) {
    if (events.rows[i].kind == EventKind::kCollision || contacts) ++count[pair_of[i]];
  }
  std::vector<std::size_t> ranked(pairs.size());
  for (std::size_t p = 0; p < ranked.size(); ++p)
    ranked[p] = p;
  std::stable_sort(ranked.begin(), ranked.end(),
                   [&](std::size_t a, std::size_t b) { return count[a] > count[b]; });
  const std::size_t named = std::min(pairs.size(), kMostPairSeries);
  const std::size_t others = pairs.size() - named;
  std::vector<std::size_t> series_of(pairs.size());
  for (std::size_t rank = 0; rank < ranked.size(); ++rank)
    series_of[ranked[rank]] = std::min(rank, named);
  const std::size_t series = named + (others > 0 ? 1 : 0);
  std::vector<std::string> collision_rows(series), contact_rows(series);
  for (std::size_t i = 0; i < events.rows.size(); ++i) {
    const EventRow& e = events.rows[i];
    const bool collision = e.kind == EventKind::kCollision;
    if (!collision && !contacts) continue;
    std::string& rows = (collision ? collision_rows : contact_rows)[series_of[pair_of[i]]];
    append_value(rows, e.time);
    rows.push_back(' ');
    append_value(rows, e.mu);
    rows.push_back('\n');
  }

  std::string script = preamble(format);
  for (std::size_t s = 0; s < series; ++s) {
    if (!contact_rows[s].empty()) append_datablock(script, fmt::format("$K{}", s), contact_rows[s]);
    if (!collision_rows[s].empty()) {
      append_datablock(script, fmt::format("$C{}", s), collision_rows[s]);
    }
  }
  std::string subtitle =
      fmt::format("{}: {} collision{}", file, collision_count, collision_count == 1 ? "" : "s");
  if (contacts) {
    subtitle.append(fmt::format(", {} micro-collision{} (kind contact)", contact_count,
                                contact_count == 1 ? "" : "s"));
  }
  subtitle.append(
      fmt::format(" between {} pair{} of bodies", pairs.size(), pairs.size() == 1 ? "" : "s"));
  append_titles(script, "Friction coefficient μ of each collision event", subtitle);
  script.append("set xlabel 'time t (s)'\n");
  script.append("set ylabel 'friction coefficient μ (dimensionless)'\n");
  script.append("set tmargin at screen 0.88\nset bmargin at screen 0.1\n");
  script.append("set lmargin at screen 0.09\n");
  const double t_hi = t_end.value_or(time.empty() ? 1.0 : time.hi);
  script.append(fmt::format("set xrange [0:{}]\n", t_hi > 0.0 ? t_hi : 1.0));
  // μ ≥ 0: the axis starts at 0 and leaves a little room above the highest point.
  const double mu_hi = mu.empty() || mu.hi <= 0.0 ? 1.0 : mu.hi * 1.08;
  script.append(fmt::format("set yrange [0:{}]\n", mu_hi));

  if (collision_count + contact_count == 0) {
    script.append("set rmargin at screen 0.97\nunset key\n");
    script.append(fmt::format(
        "set label 92 {} at graph 0.5, graph 0.5 center textcolor rgb '#666666' noenhanced\n",
        gnuplot_quote(contacts ? "no collision events in this file"
                               : "no collision events in this file (micro-collisions left out)")));
    script.append("plot NaN notitle\n");
    return script;
  }
  // The legend sits right of the axes, so it never hides a point.
  script.append("set rmargin at screen 0.76\n");
  script.append(
      "set key at screen 0.77, screen 0.88 left top vertical Left reverse samplen 1 nobox "
      "spacing 1.3\n");
  std::vector<std::string> items;
  // Series s < named is pair ranked[s], in its colour; the last, past them, the other pairs.
  const auto series_colour = [&](std::size_t s) {
    return s < named ? colour(s) : std::string(kOtherPairs);
  };
  // The grey pairs first, then the micro-collisions, so the named collisions are drawn on top.
  std::vector<std::size_t> order;
  if (others > 0) order.push_back(named);
  for (std::size_t s = 0; s < named; ++s)
    order.push_back(s);
  for (const std::size_t s : order) {
    if (contact_rows[s].empty()) continue;
    items.push_back(
        fmt::format("$K{} using 1:2 with points pointtype 7 pointsize 0.45 "
                    "linecolor rgb {} notitle",
                    s, s < named ? light_colour(s) : std::string(kOtherPairsLight)));
  }
  for (const std::size_t s : order) {
    if (collision_rows[s].empty()) continue;
    items.push_back(fmt::format(
        "$C{0} using 1:2 with points pointtype 7 pointsize 1.4 linecolor rgb {1} notitle, "
        "$C{0} using 1:2 with points pointtype 6 pointsize 1.4 linecolor rgb '#333333' notitle",
        s, series_colour(s)));
  }
  // Legend entries of their own, one per named pair (its colour, also for a pair that only has
  // micro-collisions), one for the other pairs and one for all micro-collisions: the marker
  // sizes read better than those of the data, and the legend stays narrow.
  for (std::size_t s = 0; s < series; ++s) {
    const std::string what =
        s < named ? fmt::format("{} ({})",
                                pair_label(events, pairs[ranked[s]].first, pairs[ranked[s]].second),
                                count[ranked[s]])
                  : fmt::format("{} other pair{}", others, others == 1 ? "" : "s");
    items.push_back(
        fmt::format("keyentry with points pointtype 7 pointsize 1.4 linecolor rgb {} title {} "
                    "noenhanced",
                    series_colour(s), gnuplot_quote(s < named ? shortened(what) : what)));
  }
  if (contact_count > 0) {
    items.push_back(
        "keyentry with points pointtype 7 pointsize 0.7 linecolor rgb '#A0888888' title "
        "'micro-collisions (light)'");
  }
  script.append("plot ");
  for (std::size_t i = 0; i < items.size(); ++i) {
    script.append(i == 0 ? "" : ", \\\n     ").append(items[i]);
  }
  script.append("\n");
  return script;
}

std::string velocity_script(const Trajectory& trajectory, const std::vector<std::size_t>& bodies,
                            const std::string& file, double t_end, const FigureFormat& format) {
  std::vector<std::vector<const TrajectoryRow*>> rows(trajectory.bodies.size());
  for (const TrajectoryRow& r : trajectory.rows)
    rows[r.body].push_back(&r);
  std::string script = preamble(format);
  Range speed, vx;
  std::size_t frames = 0;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    std::vector<const TrajectoryRow*>& own = rows[bodies[k]];
    // A line must follow time even if the file's rows do not.
    std::stable_sort(own.begin(), own.end(), [](const TrajectoryRow* a, const TrajectoryRow* b) {
      return a->time < b->time;
    });
    frames = std::max(frames, own.size());
    std::string data;
    for (const TrajectoryRow* r : own) {
      const double v = std::hypot(r->vx, r->vy);
      speed.add(v);
      vx.add(r->vx);
      append_value(data, r->time);
      data.push_back(' ');
      append_value(data, v);
      data.push_back(' ');
      append_value(data, r->vx);
      data.push_back('\n');
    }
    append_datablock(script, fmt::format("$V{}", k), data);
  }
  const bool legend = !bodies.empty() && bodies.size() <= kMostBodyLegend;
  std::string subtitle =
      fmt::format("{}: {} of {} bod{}, {} frames", file, bodies.size(), trajectory.bodies.size(),
                  trajectory.bodies.size() == 1 ? "y" : "ies", frames);
  if (bodies.size() > kMostBodyLegend) {
    subtitle.append(
        fmt::format(" (no legend for more than {}: choose some with --bodies)", kMostBodyLegend));
  }
  append_titles(script, "Velocity of the bodies over time", subtitle);
  // Both panels share the time axis and the same left and right edges.
  script.append(
      fmt::format("set lmargin at screen 0.09\nset rmargin at screen {}\n", legend ? 0.76 : 0.97));
  script.append(fmt::format("set xrange [0:{}]\n", t_end > 0.0 ? t_end : 1.0));
  script.append("set multiplot\n");

  // Top: speed, from 0, with room above the fastest point.
  const double speed_hi = speed.empty() || speed.hi <= 0.0 ? 1.0 : speed.hi * 1.08;
  script.append("set tmargin at screen 0.88\nset bmargin at screen 0.53\n");
  script.append("set format x ''\nunset xlabel\n");
  script.append("set ylabel 'speed |v| (m/s)'\n");
  script.append(fmt::format("set yrange [0:{}]\n", speed_hi));
  if (bodies.empty()) {
    script.append(
        "set label 92 'no moving bodies in this file' at graph 0.5, graph 0.5 center "
        "textcolor rgb '#666666' noenhanced\n");
  }
  if (legend) {
    script.append(
        "set key at screen 0.77, screen 0.88 left top vertical Left reverse samplen 2 nobox "
        "spacing 1.3\n");
  } else {
    script.append("unset key\n");
  }
  auto plot_column = [&](int column, bool titled) {
    if (bodies.empty()) {
      script.append("plot NaN notitle\n");
      return;
    }
    script.append("plot ");
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      script.append(k == 0 ? "" : ", \\\n     ");
      script.append(fmt::format("$V{} using 1:{} with lines linewidth 1.8 linecolor rgb {} ", k,
                                column, colour(k)));
      script.append(titled ? fmt::format("title {} noenhanced",
                                         gnuplot_quote(shortened(trajectory.bodies[bodies[k]])))
                           : std::string("notitle"));
    }
    script.append("\n");
  };
  plot_column(2, legend);
  script.append("unset label\n");  // the titles belong to the figure, drawn once

  // Bottom: vx, signed, around a dashed zero line.
  Range vx_axis = vx;
  vx_axis.add(0.0);
  const double pad = vx_axis.hi > vx_axis.lo ? 0.06 * (vx_axis.hi - vx_axis.lo) : 1.0;
  script.append("set tmargin at screen 0.48\nset bmargin at screen 0.1\n");
  script.append("set format x '% h'\nset xlabel 'time t (s)'\n");
  script.append("set ylabel 'horizontal velocity v_x (m/s)'\n");
  script.append(fmt::format("set yrange [{}:{}]\n", vx_axis.lo - pad, vx_axis.hi + pad));
  script.append("set xzeroaxis linetype 1 linecolor rgb '#888888' linewidth 1 dashtype 2\n");
  script.append("unset key\n");
  plot_column(3, false);
  script.append("unset multiplot\n");
  return script;
}

}  // namespace rugosim::app
