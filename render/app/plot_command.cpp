// `rugosim plot`: the paper's figure 8 (friction coefficient of each collision event over time)
// and figures 10 and 11 (velocity of bodies over time) from the telemetry CSVs, drawn by gnuplot
// (plot_figures.h) as PNG, SVG or PDF. Both inputs are read and checked completely before
// anything is drawn, so a bad file leaves no figure; each is drawn under a temporary name and
// renamed only when every drawing succeeded.
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
#include "render/app/number_option.h"
#include "render/app/plot_figures.h"
#include "render/app/scene_input.h"

namespace rugosim::app {
namespace {

namespace fs = std::filesystem;

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

// A figure drawn under a hidden temporary name beside its target; removed unless committed.
class PendingFigure {
 public:
  explicit PendingFigure(const fs::path& target)
      : target_(target),
        temporary_(target.parent_path() /
                   fmt::format(".{}.tmp-{}", target.filename().string(), ::getpid())) {}
  ~PendingFigure() {
    if (!committed_) {
      std::error_code ignored;
      fs::remove(temporary_, ignored);
    }
  }
  PendingFigure(const PendingFigure&) = delete;
  PendingFigure& operator=(const PendingFigure&) = delete;

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
  FigureFormat format;
  format.kind = o.format;
  if (!o.size.empty()) {
    const std::size_t x = o.size.find('x');
    const std::optional<double> w =
        x == std::string::npos ? std::nullopt : parse_number(o.size.substr(0, x), true);
    const std::optional<double> h =
        x == std::string::npos ? std::nullopt : parse_number(o.size.substr(x + 1), true);
    if (!w || !h || *w < 200 || *h < 150 || *w > 10000 || *h > 10000) {
      fmt::print(stderr,
                 "error: --size: expected WxH in pixels, 200..10000 by 150..10000 (e.g. "
                 "1000x600), got \"{}\"\n",
                 o.size);
      return kExitUsage;
    }
    format.width = static_cast<int>(*w);
    format.height = static_cast<int>(*h);
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
    std::unique_ptr<PendingFigure> file;
    std::string script;
  };
  std::vector<Figure> figures;
  if (events) {
    figures.push_back({std::make_unique<PendingFigure>(dir / ("friction." + format.kind)),
                       friction_script(*events, o.events_path, o.contacts, t_end, format)});
  }
  if (trajectory) {
    figures.push_back({std::make_unique<PendingFigure>(dir / ("velocity." + format.kind)),
                       velocity_script(*trajectory, bodies, o.trajectory_path, t_end, format)});
  }
  for (const Figure& f : figures) {
    try {
      const std::string warnings = run_gnuplot(f.script, f.file->temporary());
      if (!warnings.empty()) {
        fmt::print(stderr, "warning: gnuplot, drawing {}:\n{}\n", f.file->target().string(),
                   warnings);
      }
    } catch (const GnuplotError& e) {
      fmt::print(stderr, "error: drawing {}: {}\n", f.file->target().string(), e.what());
      return kExitFailure;
    }
  }
  for (const Figure& f : figures) {
    if (!f.file->commit()) return kExitFailure;
    fmt::print(stderr, "wrote {}\n", f.file->target().string());
  }
  return kExitOk;
}

}  // namespace rugosim::app
