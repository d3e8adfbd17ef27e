// The accuracy study (issue 8; README, "Accuracy"): every built-in scene at every accuracy
// preset and along each knob, measured against what it should give:
//   - the validation scenes against their closed forms (accuracy_metrics.cpp),
//   - the figure scenes against a reference run of the same scene at the tightest settings
//     (RMS distance of the bodies from the reference's, in body radii),
// with the wall time of the simulation alone (best of --repeats runs). It writes, into the
// folder given (default docs/accuracy):
//   accuracy.csv  one row per setting and scene,
//   accuracy.md   the tables: settings with their total time and errors (the Pareto front
//                 marked), the presets scene by scene, and draft's speed-up over precise,
//   pareto.png    error against wall time, one point per setting, the Pareto front drawn
//                 (gnuplot).
// Usage: accuracy_study [OUT_DIR] [--repeats N]. Run from anywhere: the scenes come from the
// source tree this was built from.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "accuracy_metrics.h"
#include "box2d_validation.h"
#include "convergence_report.h"
#include "engine/scene/scene_loader.h"
#include "engine_comparison.h"
#include "pile_report.h"
#include "render/app/gnuplot.h"

namespace rugosim::study {
namespace {

namespace fs = std::filesystem;

struct Setting {
  std::string label;  // "draft", "max_step=0.004", ...
  std::string knob;   // "preset" or the knob's key
  double value = 0.0;
  Accuracy accuracy;
};

std::vector<Setting> settings() {
  std::vector<Setting> out;
  for (const std::string& name : accuracy_preset_names()) {
    out.push_back({name, "preset", 0.0, *accuracy_preset(name)});
  }
  const std::map<std::string, std::vector<double>> sweeps = {
      {"max_step", {8e-3, 4e-3, 2e-3, 5e-4, 2.5e-4, 1.25e-4}},
      {"rest_stride", {1, 4, 64}},
      {"mid_step_rest", {0}},
      {"converging_contacts", {1}},
      {"rest_sweeps", {8, 16, 256}},
      {"toi_tolerance", {1e-5, 1e-7, 1e-11}},
      {"max_bisections", {8, 20}},
      {"newton_tolerance", {1e-6, 1e-9, 1e-14}},
      {"newton_iterations", {4, 12, 100}},
      {"seed_depth", {8, 12, 60}},
      {"contact_passes", {4, 16, 256}},
      {"contact_threshold", {5e-2, 1e-2, 1e-4, 0.0}},
  };
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    for (const double value : sweeps.at(std::string(knob.key))) {
      Accuracy a;
      knob.set(a, value);
      out.push_back({fmt::format("{}={:g}", knob.key, value), std::string(knob.key), value, a});
    }
  }
  // normal as it was before mid-step rest: micro-collisions alone, no rest steps
  // (docs/research/resting-contact.md §8.7). (mid_step_rest=0 alone keeps normal's rest steps.)
  out.push_back({"mid_step_rest=0 rest_stride=1", "mid_step_rest+rest_stride", 1.0,
                 Accuracy{.rest_stride = 1, .mid_step_rest = 0}});
  return out;
}

// The reference is checked against a run at this share of its step (the per-scene table's last
// column).
constexpr double kReferenceCheckShare = 0.25;

// The tightest settings of the study: the figure scenes' reference.
Accuracy reference_accuracy() {
  return finest_at(6.25e-5);
}

struct SceneFile {
  std::string name;
  std::string path;
  Scene scene;
  bool validation = false;
  Run reference;
  // The reference's own RMS distance from a run at a quarter of its step, in body radii. A
  // preset's error at or below it is not a measured difference.
  double reference_spread = 0.0;
  std::optional<ClosedFormError> reference_closed;  // validation scenes: the model's floor
};

struct Row {
  std::string scene;
  bool validation = false;
  double wall_s = 0.0;
  double error = 0.0;
  double limit_error = 0.0;  // RMS distance from the reference, in body radii (every scene)
  std::string measure;
  std::vector<std::pair<std::string, double>> parts;  // validation scenes: what was compared
  StepStats stats;
};

struct Summary {
  const Setting* setting = nullptr;
  std::vector<Row> rows;
  double wall_s = 0.0;            // all scenes
  double validation_error = 0.0;  // geometric mean over the validation scenes
  double figure_error = 0.0;      // geometric mean over the figure scenes
  double worst_validation = 0.0;
  std::uint64_t crossings = 0;
  std::uint64_t fallbacks = 0;
  bool front_validation = false;  // on the Pareto front of (wall, validation error)
  bool front_figure = false;
};

double geometric_mean(const std::vector<double>& values) {
  double log_sum = 0.0;
  for (const double v : values)
    log_sum += std::log(std::max(v, 1e-12));
  return values.empty() ? 0.0 : std::exp(log_sum / static_cast<double>(values.size()));
}

// Marks the summaries no other one beats on both time and error.
template <typename Error, typename Mark>
void mark_front(std::vector<Summary>& all, Error error, Mark mark) {
  for (Summary& s : all) {
    const bool dominated = std::any_of(all.begin(), all.end(), [&](const Summary& o) {
      return &o != &s && o.wall_s <= s.wall_s && error(o) <= error(s) &&
             (o.wall_s < s.wall_s || error(o) < error(s));
    });
    mark(s) = !dominated;
  }
}

void write_csv(const fs::path& path, const std::vector<Summary>& all) {
  std::ofstream out(path);
  out << "setting,knob,value,scene,kind,wall_s,error,measure,steps,bisections,fallbacks,"
         "crossings\n";
  for (const Summary& s : all) {
    for (const Row& r : s.rows) {
      out << fmt::format("{},{},{:g},{},{},{:.6g},{:.6g},\"{}\",{},{},{},{}\n", s.setting->label,
                         s.setting->knob, s.setting->value, r.scene,
                         r.validation ? "closed form" : "reference", r.wall_s, r.error, r.measure,
                         r.stats.steps, r.stats.bisections, r.stats.fallbacks, r.stats.crossings);
    }
  }
}

const Summary& by_label(const std::vector<Summary>& all, const std::string& label) {
  return *std::find_if(all.begin(), all.end(),
                       [&](const Summary& s) { return s.setting->label == label; });
}

void write_markdown(const fs::path& path, const std::vector<Summary>& all,
                    const std::vector<SceneFile>& scenes, int repeats) {
  std::ofstream out(path);
  out << "# Accuracy study\n\n"
         "Written by `build/release/bench/accuracy_study docs/accuracy` "
         "(bench/accuracy_study.cpp); wall times are the simulation alone, the best of "
      << repeats
      << " runs, on the machine that ran it. Validation error: the geometric mean over the "
         "validation scenes of each one's relative error against its closed form (below). "
         "Figure error: the geometric mean over the figure scenes of the RMS distance of the "
         "bodies from a reference run at the tightest settings (max_step 62.5 µs and the "
         "finest of every other knob), in body radii; figure12a and figure12b are chaotic "
         "piles, so any change of settings soon gives another pile and their error saturates "
         "near 1. ★ marks the Pareto front (no other setting is both faster and more "
         "accurate).\n\n";
  out << "## Every setting\n\n"
         "| setting | wall s (all scenes) | validation error | worst validation | figure error "
         "| crossings | fallbacks |\n|---|---|---|---|---|---|---|\n";
  std::vector<const Summary*> sorted;
  for (const Summary& s : all)
    sorted.push_back(&s);
  std::sort(sorted.begin(), sorted.end(),
            [](const Summary* a, const Summary* b) { return a->wall_s < b->wall_s; });
  for (const Summary* s : sorted) {
    const bool preset = s->setting->knob == "preset";
    out << fmt::format("| {}{}{} | {:.3f} | {:.3g}{} | {:.3g} | {:.3g}{} | {} | {} |\n",
                       preset ? "**" : "", s->setting->label, preset ? "**" : "", s->wall_s,
                       s->validation_error, s->front_validation ? " ★" : "", s->worst_validation,
                       s->figure_error, s->front_figure ? " ★" : "", s->crossings, s->fallbacks);
  }
  const std::vector<std::string> presets = accuracy_preset_names();
  out << "\n## The presets, scene by scene, against the method's limit\n\n"
         "Each preset's RMS distance from the reference run (the method's limit: max_step "
         "62.5 µs, every other knob at its finest, converging_contacts 1), in body radii, on "
         "every scene, and whether precise ≤ normal ≤ draft holds there (errors at or below the "
         "reference's own spread count as equal, and one error may exceed the cheaper preset's by "
         "the convergence study's 10% for noise).\n\n| scene |";
  for (const std::string& p : presets)
    out << " " << p << " |";
  for (const std::string& p : presets)
    out << " " << p << " ms |";
  out << " reference vs a quarter of its step | precise ≤ normal ≤ draft |\n|---|";
  for (std::size_t i = 0; i < 2 * presets.size() + 2; ++i)
    out << "---|";
  out << "\n";
  std::size_t ordered = 0;
  std::string unordered;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    out << "| " << scenes[k].name << " |";
    std::vector<double> errors;
    for (const std::string& p : presets) {
      errors.push_back(std::max(by_label(all, p).rows[k].limit_error, scenes[k].reference_spread));
      out << fmt::format(" {:.3g} |", by_label(all, p).rows[k].limit_error);
    }
    for (const std::string& p : presets)
      out << fmt::format(" {:.3g} |", 1e3 * by_label(all, p).rows[k].wall_s);
    // Presets are listed cheapest first: each error at most the cheaper one's, within the
    // convergence study's tolerance for noise (two presets whose errors are both the distance
    // between two contact models differ by rounding of that distance).
    bool in_order = true;
    for (std::size_t i = 1; i < errors.size(); ++i)
      in_order = in_order && errors[i] <= (1.0 + kMonotoneTolerance) * errors[i - 1];
    const bool chaotic = scenes[k].name.rfind("figure12", 0) == 0;
    if (!chaotic) {
      if (in_order) {
        ++ordered;
      } else {
        unordered += fmt::format("{}{}", unordered.empty() ? "" : ", ", scenes[k].name);
      }
    }
    out << fmt::format(" {:.3g} | {} |\n", scenes[k].reference_spread,
                       chaotic    ? "(chaotic: piles.md)"
                       : in_order ? "yes"
                                  : "**no**");
  }
  const auto non_chaotic = std::count_if(scenes.begin(), scenes.end(), [](const SceneFile& f) {
    return f.name.rfind("figure12", 0) != 0;
  });
  out << fmt::format(
      "\nIn order on {} of {} non-chaotic scenes{}. The reference vs a quarter of its step "
      "({:.3g} µs) is the reference's own error: where it is as large as the presets', those "
      "errors measure the reference as much as the presets.\n",
      ordered, non_chaotic,
      unordered.empty() ? std::string() : fmt::format(" (not: {})", unordered),
      1e6 * kReferenceCheckShare * reference_accuracy().max_step);
  out << "\n## The closed forms at each preset\n\n"
         "Relative errors against the closed forms; the last column is the reference's (the "
         "method's limit), the floor of the model that no step removes (convergence.md says "
         "why for each).\n\n| scene | quantity |";
  for (const std::string& p : presets)
    out << " " << p << " |";
  out << " limit (floor) |\n|---|---|";
  for (std::size_t i = 0; i < presets.size() + 1; ++i)
    out << "---|";
  out << "\n";
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    if (!scenes[k].validation) continue;
    const std::vector<std::pair<std::string, double>>& parts =
        by_label(all, presets.front()).rows[k].parts;
    for (std::size_t q = 0; q < parts.size(); ++q) {
      out << "| " << scenes[k].name << " | " << parts[q].first << " |";
      for (const std::string& p : presets)
        out << fmt::format(" {:.2e} |", by_label(all, p).rows[k].parts[q].second);
      out << fmt::format(" {:.2e} |\n", scenes[k].reference_closed->parts[q].second);
    }
  }
  out << "\n## Draft against precise on figure12a\n\n";
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    if (scenes[k].name != "figure12a") continue;
    const double draft = by_label(all, "draft").rows[k].wall_s;
    const double precise = by_label(all, "precise").rows[k].wall_s;
    out << fmt::format(
        "draft {:.1f} ms, normal {:.1f} ms, precise {:.1f} ms: draft is {:.1f}× faster than "
        "precise.\n",
        1e3 * draft, 1e3 * by_label(all, "normal").rows[k].wall_s, 1e3 * precise, precise / draft);
  }
  out << "\n## Knobs\n\n";
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    out << fmt::format("- `{}`: {} ({}; normal {:g}, draft {:g}, precise {:g})\n", knob.key,
                       knob.help, knob.expectation(), knob.get(*accuracy_preset("normal")),
                       knob.get(*accuracy_preset("draft")), knob.get(*accuracy_preset("precise")));
  }
}

// Two panels, validation error and figure error against the total wall time, log-log; the
// presets labelled, the Pareto front as a line.
void write_plot(const fs::path& path, const std::vector<Summary>& all) {
  auto block = [&](const std::string& name, auto error, auto front) {
    std::string data = "$" + name + " << EOD\n";
    std::vector<const Summary*> points;
    for (const Summary& s : all) {
      if (!front || (s.*front)) points.push_back(&s);
    }
    std::sort(points.begin(), points.end(),
              [](const Summary* a, const Summary* b) { return a->wall_s < b->wall_s; });
    for (const Summary* s : points) {
      data += fmt::format("{:.6g} {:.6g} \"{}\" {}\n", s->wall_s, std::max(error(*s), 1e-12),
                          s->setting->label, s->setting->knob == "preset" ? 1 : 0);
    }
    return data + "EOD\n";
  };
  auto validation = [](const Summary& s) { return s.validation_error; };
  auto figure = [](const Summary& s) { return s.figure_error; };
  std::string script = "set terminal pngcairo size 1400,560 font 'Sans,10'\n";
  script += block("val", validation, static_cast<bool Summary::*>(nullptr));
  script += block("valfront", validation, &Summary::front_validation);
  script += block("fig", figure, static_cast<bool Summary::*>(nullptr));
  script += block("figfront", figure, &Summary::front_figure);
  script += R"(set multiplot layout 1,2
set logscale xy
set grid
set key top right
set xlabel 'wall time of all 13 scenes (s)'
set style line 1 lc rgb '#4a6fa5' pt 7 ps 1.0
set style line 2 lc rgb '#c0392b' lw 2
set style line 3 lc rgb '#222222' pt 5 ps 1.6
set title 'validation scenes: error against the closed forms'
set ylabel 'relative error (geometric mean)'
plot $val using 1:2 with points ls 1 title 'a setting', \
     $valfront using 1:2 with steps ls 2 title 'Pareto front', \
     $val using ($4 == 1 ? $1 : 1/0):2 with points ls 3 title 'presets', \
     $val using ($4 == 1 ? $1 : 1/0):2:3 with labels offset 0,1.2 notitle
set title 'figure scenes: distance from the reference run'
set ylabel 'RMS distance in body radii (geometric mean)'
plot $fig using 1:2 with points ls 1 title 'a setting', \
     $figfront using 1:2 with steps ls 2 title 'Pareto front', \
     $fig using ($4 == 1 ? $1 : 1/0):2 with points ls 3 title 'presets', \
     $fig using ($4 == 1 ? $1 : 1/0):2:3 with labels offset 0,1.2 notitle
unset multiplot
)";
  app::run_gnuplot(script, path.string());
}

// Every setting on every scene: accuracy.csv, accuracy.md, pareto.png.
void settings_part(std::vector<SceneFile>& scenes, const fs::path& out_dir, int repeats) {
  for (SceneFile& f : scenes) {
    fmt::print(stderr, "reference run of {}\n", f.name);
    f.reference = run_scene(f.scene, f.path, reference_accuracy(), 1);
    f.reference_closed = closed_form_error(f.name, f.scene, f.reference);
    Accuracy finer = reference_accuracy();
    finer.max_step *= kReferenceCheckShare;
    f.reference_spread = trajectory_error(run_scene(f.scene, f.path, finer, 1), f.reference);
  }

  const std::vector<Setting> all_settings = settings();
  std::vector<Summary> summaries;
  for (const Setting& setting : all_settings) {
    Summary s;
    s.setting = &setting;
    std::vector<double> validation, figure;
    for (const SceneFile& f : scenes) {
      const Run run = run_scene(f.scene, f.path, setting.accuracy, repeats);
      Row row;
      row.scene = f.name;
      row.validation = f.validation;
      row.wall_s = run.wall_s;
      row.stats = run.stats;
      row.limit_error = trajectory_error(run, f.reference);
      const std::optional<ClosedFormError> closed = closed_form_error(f.name, f.scene, run);
      if (f.validation && !closed) {
        throw std::runtime_error(f.name +
                                 " is a validation scene without a closed form in "
                                 "bench/accuracy_metrics.cpp");
      }
      if (f.validation) {
        const ClosedFormError& e = *closed;
        row.error = e.error;
        row.measure = e.what;
        row.parts = e.parts;
        validation.push_back(e.error);
        s.worst_validation = std::max(s.worst_validation, e.error);
      } else {
        row.error = row.limit_error;
        row.measure = "RMS distance from the reference, in body radii";
        figure.push_back(row.error);
      }
      s.wall_s += run.wall_s;
      s.crossings += run.stats.crossings;
      s.fallbacks += run.stats.fallbacks;
      s.rows.push_back(std::move(row));
    }
    s.validation_error = geometric_mean(validation);
    s.figure_error = geometric_mean(figure);
    fmt::print(stderr, "{:24} {:8.3f} s  validation {:.3g}  figures {:.3g}\n", setting.label,
               s.wall_s, s.validation_error, s.figure_error);
    summaries.push_back(std::move(s));
  }
  mark_front(
      summaries, [](const Summary& s) { return s.validation_error; },
      [](Summary& s) -> bool& { return s.front_validation; });
  mark_front(
      summaries, [](const Summary& s) { return s.figure_error; },
      [](Summary& s) -> bool& { return s.front_figure; });

  write_csv(out_dir / "accuracy.csv", summaries);
  write_markdown(out_dir / "accuracy.md", summaries, scenes, repeats);
  write_plot(out_dir / "pareto.png", summaries);
  fmt::print(stderr, "wrote {}/accuracy.csv, accuracy.md and pareto.png\n", out_dir.string());
}

// Whether a scene's trajectory can be compared along the step: the piles are chaotic (any
// change of settings soon gives another pile) and the close-up has nothing in contact.
bool converges(const std::string& name) {
  for (const char* prefix : {"validation_", "figure06_", "figure09_"}) {
    if (name.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// Each non-chaotic scene along the step: convergence.csv, convergence.md, convergence.png.
void convergence_part(const std::vector<SceneFile>& scenes, const fs::path& out_dir, int repeats) {
  std::vector<SceneConvergence> results;
  for (const SceneFile& f : scenes) {
    if (!converges(f.name)) continue;
    fmt::print(stderr, "convergence of {}\n", f.name);
    results.push_back(study_convergence(f.name, f.scene, f.path, convergence_steps(), repeats));
    const SceneConvergence& r = results.back();
    for (const ConvergencePoint& p : r.points) {
      fmt::print(stderr, "  {:8g} ms {:9.4f} s  error {:.3e}  from 2h {:.3e}{}\n", 1e3 * p.step,
                 p.wall_s, p.error, p.previous,
                 p.closed ? fmt::format("  closed form {:.3e}", p.closed->error) : "");
    }
    fmt::print(stderr, "  p {:.2f}  order {:.2f}  monotone {}{}\n", r.richardson_order, r.order,
               r.monotone, r.floor ? fmt::format("  floor {:.3e}", r.floor->error) : "");
  }
  write_convergence_csv(out_dir / "convergence.csv", results);
  write_convergence_markdown(out_dir / "convergence.md", results);
  write_convergence_plot(out_dir / "convergence.png", results);
  fmt::print(stderr, "wrote {}/convergence.csv, convergence.md and convergence.png\n",
             out_dir.string());
}

// The chaotic piles (figure12a, figure12b) by the statistics of an ensemble per preset and at
// the finest settings: piles.csv, piles.md.
void piles_part(const std::vector<SceneFile>& scenes, const fs::path& out_dir,
                std::size_t members) {
  std::vector<PileEnsemble> ensembles;
  for (const SceneFile& f : scenes) {
    if (f.name.rfind("figure12", 0) != 0) continue;
    std::vector<std::pair<std::string, Accuracy>> settings;
    for (const std::string& name : accuracy_preset_names())
      settings.emplace_back(name, *accuracy_preset(name));
    settings.emplace_back("finest", finest_at(convergence_steps().back()));
    for (const auto& [label, accuracy] : settings) {
      ensembles.push_back(run_pile_ensemble(f.name, f.scene, f.path, label, accuracy, members));
      const PileEnsemble& e = ensembles.back();
      fmt::print(stderr, "{} {:8} {:7.2f} s  settle {:.2f}±{:.2f} s  height {:.4f}±{:.4f} m\n",
                 f.name, label, e.wall_s, e.settle_time().mean, e.settle_time().half_width,
                 e.com_height().mean, e.com_height().half_width);
    }
  }
  write_piles_csv(out_dir / "piles.csv", ensembles);
  write_piles_markdown(out_dir / "piles.md", ensembles);
  fmt::print(stderr, "wrote {}/piles.csv and piles.md\n", out_dir.string());
}

// The validation scenes in Box2D 2.4.1 (box2d_scene.h) and rugosim's presets on the same
// closed forms: box2d.csv, box2d.md (Box2D's table, then the two engines compared).
void box2d_part(const std::vector<SceneFile>& scenes, const fs::path& out_dir, int repeats) {
  std::vector<std::pair<std::string, std::string>> validation;
  std::vector<EngineRun> runs;
  for (const SceneFile& f : scenes) {
    if (!f.validation) continue;
    validation.emplace_back(f.name, f.path);
    for (const std::string& preset : accuracy_preset_names()) {
      const Run run = run_scene(f.scene, f.path, *accuracy_preset(preset), repeats);
      runs.push_back(
          {"rugosim", preset, f.name, run.wall_s, *closed_form_error(f.name, f.scene, run)});
    }
  }
  fmt::print(stderr, "Box2D on {} validation scenes\n", validation.size());
  const std::vector<bench::Box2dClosedForm> box2d =
      bench::run_box2d_validation(validation, repeats);
  for (const bench::Box2dClosedForm& r : box2d) {
    if (!r.error) continue;
    // The engine has its own column: "box2d 60 Hz" is "60 Hz" of Box2D.
    const std::string setting = r.setting.rfind("box2d ", 0) == 0 ? r.setting.substr(6) : r.setting;
    runs.push_back({"Box2D", setting, r.scene, r.wall_s, *r.error});
  }
  bench::write_box2d_csv(out_dir / "box2d.csv", box2d);
  bench::write_box2d_markdown(out_dir / "box2d.md", box2d);
  append_engine_comparison(out_dir / "box2d.md", runs);
  fmt::print(stderr, "wrote {}/box2d.csv and box2d.md\n", out_dir.string());
}

// A mistake on the command line (exit 2, as rugosim's own).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run(int argc, char** argv) {
  fs::path out_dir = fs::path(RUGOSIM_SOURCE_DIR) / "docs" / "accuracy";
  int repeats = 3;
  std::size_t members = 16;
  std::string part = "all";
  bool out_dir_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      fmt::print(
          "Usage: accuracy_study [OUT_DIR] [--repeats N] [--members M]\n"
          "                      [--part all|settings|convergence|piles|box2d]\n"
          "Runs every built-in scene at every preset and along each accuracy knob and\n"
          "writes accuracy.csv, accuracy.md and pareto.png into OUT_DIR (default\n"
          "docs/accuracy of the source tree); runs each non-chaotic scene along the step\n"
          "and writes convergence.csv, convergence.md and convergence.png; runs the piles\n"
          "(figure12a, figure12b) as ensembles of M perturbed copies (16) per preset and\n"
          "at the finest settings and writes piles.csv and piles.md. N: timed runs per\n"
          "setting, best kept (3). Runs the validation scenes in Box2D 2.4.1 too and\n"
          "writes box2d.csv and box2d.md (the engines compared). --part: only one.\n");
      return 0;
    }
    if (arg == "--repeats") {
      char* end = nullptr;
      const long n = i + 1 < argc ? std::strtol(argv[i + 1], &end, 10) : 0;
      if (i + 1 >= argc || *end != '\0' || n < 1 || n > 1000)
        throw UsageError("--repeats expects a whole number from 1 to 1000");
      repeats = static_cast<int>(n);
      ++i;
    } else if (arg == "--members") {
      char* end = nullptr;
      const long n = i + 1 < argc ? std::strtol(argv[i + 1], &end, 10) : 0;
      if (i + 1 >= argc || *end != '\0' || n < 2 || n > 1000)
        throw UsageError("--members expects a whole number from 2 to 1000");
      members = static_cast<std::size_t>(n);
      ++i;
    } else if (arg == "--part") {
      part = i + 1 < argc ? argv[i + 1] : "";
      if (part != "all" && part != "settings" && part != "convergence" && part != "piles" &&
          part != "box2d")
        throw UsageError("--part expects all, settings, convergence, piles or box2d");
      ++i;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + arg + " (see --help)");
    } else if (out_dir_given) {
      throw UsageError("one OUT_DIR expected, got " + out_dir.string() + " and " + arg);
    } else {
      out_dir = arg;
      out_dir_given = true;
    }
  }
  fs::create_directories(out_dir);

  std::vector<SceneFile> scenes;
  for (const auto& entry : fs::directory_iterator(fs::path(RUGOSIM_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    // The benchmark piles measure speed (bench_pile); figure12a and figure12b are the chaotic
    // piles of the study, and a reference run of 1,000 bodies at 62.5 µs would take hours.
    if (entry.path().stem().string().rfind("pile_", 0) == 0) continue;
    // figure12a_slide simulates what figure12a does (it only dresses the frames); rock_closeup
    // is a still of one rock with nothing to touch.
    if (entry.path().stem() == "figure12a_slide" || entry.path().stem() == "rock_closeup") continue;
    SceneFile f;
    f.name = entry.path().stem().string();
    f.path = entry.path().string();
    const SceneLoad load = load_scene_file(f.path);
    if (!load.ok()) throw std::runtime_error(f.path + " does not load");
    f.scene = load.scene;
    f.validation = f.name.rfind("validation_", 0) == 0;
    scenes.push_back(std::move(f));
  }
  std::sort(scenes.begin(), scenes.end(),
            [](const SceneFile& a, const SceneFile& b) { return a.name < b.name; });
  if (part == "all" || part == "settings") settings_part(scenes, out_dir, repeats);
  if (part == "all" || part == "convergence") convergence_part(scenes, out_dir, repeats);
  if (part == "all" || part == "piles") piles_part(scenes, out_dir, members);
  if (part == "all" || part == "box2d") box2d_part(scenes, out_dir, repeats);
  return 0;
}

}  // namespace
}  // namespace rugosim::study

int main(int argc, char** argv) {
  try {
    return rugosim::study::run(argc, argv);
  } catch (const rugosim::study::UsageError& e) {
    fmt::print(stderr, "accuracy_study: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "accuracy_study: {}\n", e.what());
    return 1;
  }
}
