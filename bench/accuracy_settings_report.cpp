#include "accuracy_settings_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/core.h>

#include "convergence.h"
#include "render/app/gnuplot.h"

namespace rugosim::study {

namespace fs = std::filesystem;

// The tightest settings of the study: the figure scenes' reference.
Accuracy reference_accuracy() {
  return finest_at(6.25e-5);
}

double geometric_mean(const std::vector<double>& values) {
  double log_sum = 0.0;
  for (const double v : values)
    log_sum += std::log(std::max(v, kErrorResolution));
  return values.empty() ? 0.0 : std::exp(log_sum / static_cast<double>(values.size()));
}

void write_settings_csv(const fs::path& path, const std::vector<Summary>& all) {
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

namespace {

const Summary& by_label(const std::vector<Summary>& all, const std::string& label) {
  return *std::find_if(all.begin(), all.end(),
                       [&](const Summary& s) { return s.setting->label == label; });
}

}  // namespace

void write_settings_markdown(const fs::path& path, const std::vector<Summary>& all,
                             const std::vector<SceneFile>& scenes, int repeats) {
  std::ofstream out(path);
  out << "# Accuracy study\n\n"
         "Written by `build/release/bench/accuracy_study docs/accuracy` "
         "(bench/accuracy_study.cpp); wall times are the simulation alone, the best of "
      << repeats
      << " runs, on the machine that ran it. Validation error: the geometric mean over the "
         "validation scenes of each one's relative error against its closed form (below; "
         "errors under 1e-7, single precision's rounding, count as 1e-7). "
         "Figure error: the geometric mean over the figure scenes of the RMS distance of the "
         "bodies from a reference run at the tightest settings (max_step 62.5 µs and the "
         "finest of every other knob), in body radii; figure12a and figure12b are chaotic "
         "piles, so any change of settings soon gives another pile and their error saturates "
         "near 1. Box2D 2.4.1's settings are points on the validation panel of pareto.png "
         "(box2d.md). ★ marks the Pareto front (no other setting is both faster and more "
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
void write_pareto_plot(const fs::path& path, const std::vector<Summary>& all,
                       const std::vector<PeerPoint>& peers) {
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
  script += "$peers << EOD\n";
  for (const PeerPoint& p : peers) {
    script += fmt::format("{:.6g} {:.6g} \"{}\"\n", p.wall_s, std::max(p.validation_error, 1e-12),
                          p.label);
  }
  script += "EOD\n";
  script += R"(set multiplot layout 1,2
set logscale xy
set grid
set key top right
set xlabel 'wall time of all the scenes of the study (s)'
set style line 1 lc rgb '#4a6fa5' pt 7 ps 1.0
set style line 2 lc rgb '#c0392b' lw 2
set style line 3 lc rgb '#222222' pt 5 ps 1.6
set style line 4 lc rgb '#e67e22' pt 9 ps 1.6
set title 'validation scenes: error against the closed forms'
set ylabel 'relative error (geometric mean)'
plot $val using 1:2 with points ls 1 title 'a setting', \
     $valfront using 1:2 with steps ls 2 title 'Pareto front', \
     $val using ($4 == 1 ? $1 : 1/0):2 with points ls 3 title 'presets', \
     $val using ($4 == 1 ? $1 : 1/0):2:3 with labels offset 0,1.2 notitle, \
     $peers using 1:2 with points ls 4 title 'Box2D 2.4.1', \
     $peers using 1:2:3 with labels offset 0,-1.2 notitle
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

}  // namespace rugosim::study
