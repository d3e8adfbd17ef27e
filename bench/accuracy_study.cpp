// The accuracy study (issues 8 and 17; README, "Accuracy"): every built-in scene at every
// accuracy preset and along each knob, measured against what it should give:
//   - the validation scenes against their closed forms (accuracy_metrics.cpp),
//   - every scene against a reference run of the same scene at the tightest settings (the
//     method's limit; RMS distance of the bodies from the reference's, in body radii),
// with the wall time of the simulation alone (best of --repeats runs); the non-chaotic scenes
// along the step (convergence.h); the chaotic piles by the statistics of ensembles
// (pile_statistics.h); and the validation scenes in Box2D 2.4.1 (box2d_validation.h). It
// writes, into the folder given (default docs/accuracy):
//   accuracy.csv, accuracy.md, pareto.png   the settings (accuracy_settings_report.h),
//   convergence.csv, .md, .png              the convergence with the step,
//   piles.csv, piles.md                     the piles' statistics,
//   box2d.csv, box2d.md                     Box2D and the two engines compared.
// Usage: accuracy_study [OUT_DIR] [--repeats N] [--members M] [--part P] (--help). Run from
// anywhere: the scenes come from the source tree this was built from.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "accuracy_metrics.h"
#include "accuracy_settings_report.h"
#include "box2d_validation.h"
#include "convergence_report.h"
#include "engine/scene/scene_loader.h"
#include "engine_comparison.h"
#include "pile_report.h"

namespace rugosim::study {
namespace {

namespace fs = std::filesystem;

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
      {"soft_rest", {0, 4, 16}},
      {"soft_rest_hertz", {30, 120}},
      {"soft_rest_island", {1}},
      {"toi_tolerance", {1e-5, 1e-7, 1e-11}},
      {"max_bisections", {8, 20}},
      {"newton_tolerance", {1e-6, 1e-9, 1e-14}},
      {"newton_iterations", {4, 12, 100}},
      {"seed_depth", {8, 12, 60}},
      {"contact_passes", {4, 16, 256}},
      {"contact_threshold", {5e-2, 1e-2, 1e-4, 0.0}},
  };
  for (const AccuracyKnob& knob : accuracy_knobs()) {
    const auto sweep = sweeps.find(std::string(knob.key));
    if (sweep == sweeps.end()) {
      throw std::logic_error(
          fmt::format("accuracy_study: no values to try for the knob {}", knob.key));
    }
    for (const double value : sweep->second) {
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

  // Box2D on the validation scenes: a point per setting that runs them all (its 32-gon disks
  // run only the scenes with a disk).
  std::vector<std::pair<std::string, std::string>> validation;
  for (const SceneFile& f : scenes) {
    if (f.validation) validation.emplace_back(f.name, f.path);
  }
  std::vector<PeerPoint> peers;
  const std::vector<bench::Box2dClosedForm> box2d =
      bench::run_box2d_validation(validation, repeats);
  for (const bench::Box2dSetting& setting : bench::box2d_validation_settings()) {
    PeerPoint point{setting.label, 0.0, 0.0};
    std::vector<double> errors;
    for (const bench::Box2dClosedForm& r : box2d) {
      if (r.setting != setting.label || !r.error) continue;
      point.wall_s += r.wall_s;
      errors.push_back(r.error->error);
    }
    if (errors.size() != validation.size()) continue;
    point.validation_error = geometric_mean(errors);
    peers.push_back(point);
  }
  write_settings_csv(out_dir / "accuracy.csv", summaries);
  write_settings_markdown(out_dir / "accuracy.md", summaries, scenes, repeats);
  write_pareto_plot(out_dir / "pareto.png", summaries, peers);
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
