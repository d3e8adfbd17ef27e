// `rugosim plot`: the paper's figure 8 (friction coefficient of each collision event over time)
// and figures 10 and 11 (velocity of bodies over time) from the telemetry CSVs, drawn by gnuplot
// as PNG. Both inputs are read and checked completely before anything is drawn, so a bad file
// leaves no PNG; each PNG is drawn under a temporary name and renamed only when every drawing
// succeeded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "engine/dynamics/telemetry.h"
#include "engine/scene/scene_loader.h"
#include "render/app/commands.h"
#include "render/app/csv_reader.h"
#include "render/app/gnuplot.h"
#include "render/app/scene_input.h"

namespace rugosim::app {
namespace {

namespace fs = std::filesystem;

// Distinct colours that stay apart for colour-blind readers (the Tableau 10 hues).
constexpr std::string_view kColours[] = {"1f77b4", "d62728", "2ca02c", "ff7f0e", "9467bd",
                                         "8c564b", "e377c2", "17becf", "7f7f7f", "bcbd22"};
constexpr std::size_t kColourCount = std::size(kColours);

// Beyond these, one series or legend entry per pair or body is clutter, not information.
constexpr std::size_t kMostPairSeries = 6;
constexpr std::size_t kMostBodyLegend = 12;

std::string colour(std::size_t i) {
  return fmt::format("'#{}'", kColours[i % kColourCount]);
}

// The same hue, mostly transparent (gnuplot's #AARRGGBB counts AA as transparency).
std::string light_colour(std::size_t i) {
  return fmt::format("'#B0{}'", kColours[i % kColourCount]);
}

// A value for a datablock: shortest exact form; NaN (gnuplot skips the point) for a value that
// is not finite.
void append_value(std::string& out, double x) {
  if (std::isfinite(x)) {
    append_number(out, x);
  } else {
    out.append("NaN");
  }
}

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double x) {
    if (!std::isfinite(x)) return;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  bool empty() const { return !(lo <= hi); }
};

// A name as the user wrote it in a CSV: quoted when it holds a comma or a quote.
std::string csv_name(const std::string& name) {
  std::string out;
  append_csv_field(out, name);
  return out;
}

std::string name_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) {
    if (!out.empty()) out.append(", ");
    out.append(csv_name(name));
  }
  return out;
}

// Settings shared by both figures: a 1000x600 PNG in a clean sans-serif font, a light grid
// behind the data, an open frame.
std::string preamble() {
  return "set encoding utf8\n"
         "set terminal pngcairo size 1000,600 enhanced font 'DejaVu Sans,11' linewidth 1.2 "
         "background rgb 'white'\n"
         "set border 3 linecolor rgb '#444444'\n"
         "set tics nomirror out\n"
         "set grid xtics ytics linetype 1 linecolor rgb '#e4e4e4' linewidth 1\n"
         "set grid back\n"
         "set title font ',14'\n";
}

// The figure's title and, under it in grey, what it was drawn from (file names are shown as
// they are, never read as enhanced-text markup).
void append_titles(std::string& script, std::string_view title, std::string_view subtitle) {
  script.append("set label 90 ").append(gnuplot_quote(title));
  script.append(" at screen 0.5, screen 0.965 center font ',14' noenhanced front\n");
  script.append("set label 91 ").append(gnuplot_quote(subtitle));
  script.append(
      " at screen 0.5, screen 0.925 center font ',10' textcolor rgb '#666666' noenhanced "
      "front\n");
}

void append_datablock(std::string& script, std::string_view name, const std::string& rows) {
  script.append(name).append(" << EOD\n").append(rows).append("EOD\n");
}

// A legend entry cut to fit beside the axes.
std::string shortened(const std::string& text) {
  constexpr std::size_t kLongest = 24;
  if (text.size() <= kLongest) return text;
  std::size_t cut = kLongest - 1;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80)
    --cut;  // UTF-8
  return text.substr(0, cut) + "…";
}

std::string pair_label(const Events& events, std::size_t a, std::size_t b) {
  return fmt::format("{} – {}", events.bodies[a], events.bodies[b]);
}

// Figure 8: μ of every collision event over time, one colour per pair of bodies when few; the
// micro-collisions as small light dots underneath.
std::string friction_script(const Events& events, const std::string& file, bool contacts,
                            std::optional<double> t_end) {
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
  const bool per_pair = pairs.size() <= kMostPairSeries;
  const std::size_t series = per_pair ? pairs.size() : 1;
  std::vector<std::string> collision_rows(series), contact_rows(series);
  for (std::size_t i = 0; i < events.rows.size(); ++i) {
    const EventRow& e = events.rows[i];
    const bool collision = e.kind == EventKind::kCollision;
    if (!collision && !contacts) continue;
    std::string& rows = (collision ? collision_rows : contact_rows)[per_pair ? pair_of[i] : 0];
    append_value(rows, e.time);
    rows.push_back(' ');
    append_value(rows, e.mu);
    rows.push_back('\n');
  }

  std::string script = preamble();
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
  // Micro-collisions first, so the collisions are drawn over them.
  for (std::size_t s = 0; s < series; ++s) {
    if (contact_rows[s].empty()) continue;
    items.push_back(
        fmt::format("$K{} using 1:2 with points pointtype 7 pointsize 0.45 "
                    "linecolor rgb {} notitle",
                    s, per_pair ? light_colour(s) : std::string("'#A0888888'")));
  }
  for (std::size_t s = 0; s < series; ++s) {
    if (collision_rows[s].empty()) continue;
    items.push_back(fmt::format(
        "$C{0} using 1:2 with points pointtype 7 pointsize 1.4 linecolor rgb {1} notitle, "
        "$C{0} using 1:2 with points pointtype 6 pointsize 1.4 linecolor rgb '#333333' notitle",
        s, colour(s)));
  }
  // Legend entries of their own, one per pair (its colour, also for a pair that only has
  // micro-collisions) and one for all micro-collisions: the marker sizes read better than those
  // of the data, and the legend stays narrow.
  for (std::size_t s = 0; s < series; ++s) {
    if (!per_pair && collision_count == 0) continue;
    const std::string what =
        per_pair ? pair_label(events, pairs[s].first, pairs[s].second) : "collisions";
    items.push_back(
        fmt::format("keyentry with points pointtype 7 pointsize 1.4 linecolor rgb {} title {} "
                    "noenhanced",
                    colour(s), gnuplot_quote(shortened(what))));
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

// Figures 10 and 11: the speed |v| (top) and vx (bottom) of each chosen body over time, one
// colour per body in both panels.
std::string velocity_script(const Trajectory& trajectory, const std::vector<std::size_t>& bodies,
                            const std::string& file, double t_end) {
  std::vector<std::vector<const TrajectoryRow*>> rows(trajectory.bodies.size());
  for (const TrajectoryRow& r : trajectory.rows)
    rows[r.body].push_back(&r);
  std::string script = preamble();
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

// Appends the names of a --bodies value to `names`: separated by commas, spaces around a name
// dropped; a name in double quotes (inner quotes doubled, as in CSV) may hold commas and keeps
// its spaces. False when a quote is not closed or text follows a closing quote.
bool split_names(std::string_view value, std::vector<std::string>& names) {
  std::size_t i = 0;
  auto skip_spaces = [&] {
    while (i < value.size() && value[i] == ' ')
      ++i;
  };
  while (true) {
    skip_spaces();
    std::string name;
    if (i < value.size() && value[i] == '"') {
      for (++i;; ++i) {
        if (i >= value.size()) return false;
        if (value[i] == '"') {
          if (i + 1 < value.size() && value[i + 1] == '"') {
            name.push_back('"');
            ++i;
            continue;
          }
          ++i;
          break;
        }
        name.push_back(value[i]);
      }
      skip_spaces();
      if (i < value.size() && value[i] != ',') return false;
    } else {
      const std::size_t comma = std::min(value.find(',', i), value.size());
      std::string_view bare = value.substr(i, comma - i);
      while (!bare.empty() && bare.back() == ' ')
        bare.remove_suffix(1);
      name = bare;
      i = comma;
    }
    if (!name.empty()) names.push_back(std::move(name));
    if (i >= value.size()) return true;
    ++i;  // the comma
  }
}

// The indices in `trajectory.bodies` named by the --bodies values (each a CSV record of names),
// in the order given, or every body when none is given. nullopt after printing an error.
std::optional<std::vector<std::size_t>> choose_bodies(const Trajectory& trajectory,
                                                      const PlotOptions& o) {
  std::vector<std::size_t> chosen;
  if (o.bodies.empty()) {
    for (std::size_t i = 0; i < trajectory.bodies.size(); ++i)
      chosen.push_back(i);
    return chosen;
  }
  std::vector<std::string> names;
  for (const std::string& value : o.bodies) {
    if (!split_names(value, names)) {
      fmt::print(stderr,
                 "error: --bodies {}: a quoted name is not closed, or text follows its "
                 "closing quote\n",
                 value);
      return std::nullopt;
    }
  }
  std::vector<std::string> unknown;
  for (const std::string& name : names) {
    const auto it = std::find(trajectory.bodies.begin(), trajectory.bodies.end(), name);
    if (it == trajectory.bodies.end()) {
      unknown.push_back(name);
      continue;
    }
    const auto index = static_cast<std::size_t>(it - trajectory.bodies.begin());
    if (std::find(chosen.begin(), chosen.end(), index) == chosen.end()) chosen.push_back(index);
  }
  if (unknown.empty()) return chosen;
  for (const std::string& name : unknown) {
    const std::string guess = closest_match(name, trajectory.bodies);
    fmt::print(stderr, "error: --bodies: no body {} in {}{}\n", csv_name(name), o.trajectory_path,
               guess.empty() ? std::string() : fmt::format(" (did you mean {}?)", csv_name(guess)));
  }
  fmt::print(stderr, "{}: its bodies are: {}\n", o.trajectory_path,
             trajectory.bodies.empty() ? std::string("(none: no moving body)")
                                       : name_list(trajectory.bodies));
  return std::nullopt;
}

// A PNG drawn under a hidden temporary name beside its target; removed unless committed.
class PendingPng {
 public:
  explicit PendingPng(const fs::path& target)
      : target_(target),
        temporary_(target.parent_path() /
                   fmt::format(".{}.tmp-{}", target.filename().string(), ::getpid())) {}
  ~PendingPng() {
    if (!committed_) {
      std::error_code ignored;
      fs::remove(temporary_, ignored);
    }
  }
  PendingPng(const PendingPng&) = delete;
  PendingPng& operator=(const PendingPng&) = delete;

  const fs::path& target() const { return target_; }
  std::string temporary() const { return temporary_.string(); }
  // Renames over the target; false after printing why.
  bool commit() {
    std::error_code error;
    fs::rename(temporary_, target_, error);
    if (error) {
      fmt::print(stderr, "error: {}: cannot replace: {}\n", target_.string(), error.message());
      return false;
    }
    committed_ = true;
    return true;
  }

 private:
  fs::path target_;
  fs::path temporary_;
  bool committed_ = false;
};

}  // namespace

int run_plot(const PlotOptions& o) {
  if (o.events_path.empty() && o.trajectory_path.empty()) {
    fmt::print(stderr, "error: plot needs --events FILE.csv or --trajectory FILE.csv (or both)\n");
    return kExitUsage;
  }
  if (!o.bodies.empty() && o.trajectory_path.empty()) {
    fmt::print(stderr,
               "error: --bodies chooses the bodies of the velocity plot: it needs "
               "--trajectory FILE.csv\n");
    return kExitUsage;
  }
  std::optional<Events> events;
  std::optional<Trajectory> trajectory;
  std::vector<std::size_t> bodies;
  try {
    if (!o.events_path.empty()) events = read_events_csv(o.events_path);
    if (!o.trajectory_path.empty()) trajectory = read_trajectory_csv(o.trajectory_path);
    if (trajectory) {
      std::optional<std::vector<std::size_t>> chosen = choose_bodies(*trajectory, o);
      if (!chosen) return kExitUsage;
      bodies = std::move(*chosen);
    }
  } catch (const CsvError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  }

  // Both figures span the same time, that of the trajectory when there is one, so they can be
  // read side by side.
  Range time;
  if (trajectory) {
    for (const TrajectoryRow& r : trajectory->rows)
      time.add(r.time);
  } else {
    for (const EventRow& e : events->rows)
      time.add(e.time);
  }
  const double t_end = time.empty() || time.hi <= 0.0 ? 1.0 : time.hi;

  const fs::path dir(o.output_dir);
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    fmt::print(stderr, "error: {}: cannot create the output folder: {}\n", o.output_dir,
               error ? error.message() : std::string("a file of that name exists"));
    return kExitFailure;
  }

  struct Figure {
    std::unique_ptr<PendingPng> png;
    std::string script;
  };
  std::vector<Figure> figures;
  if (events) {
    figures.push_back({std::make_unique<PendingPng>(dir / "friction.png"),
                       friction_script(*events, o.events_path, o.contacts, t_end)});
  }
  if (trajectory) {
    figures.push_back({std::make_unique<PendingPng>(dir / "velocity.png"),
                       velocity_script(*trajectory, bodies, o.trajectory_path, t_end)});
  }
  for (const Figure& f : figures) {
    try {
      const std::string warnings = run_gnuplot(f.script, f.png->temporary());
      if (!warnings.empty()) {
        fmt::print(stderr, "warning: gnuplot, drawing {}:\n{}\n", f.png->target().string(),
                   warnings);
      }
    } catch (const GnuplotError& e) {
      fmt::print(stderr, "error: drawing {}: {}\n", f.png->target().string(), e.what());
      return kExitFailure;
    }
  }
  for (const Figure& f : figures) {
    if (!f.png->commit()) return kExitFailure;
    fmt::print(stderr, "wrote {}\n", f.png->target().string());
  }
  return kExitOk;
}

}  // namespace rugosim::app
