#include "pile_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include <fmt/core.h>

namespace rugosim::study {
namespace {

std::string format_estimate(const Estimate& e, const char* format) {
  return fmt::format(fmt::runtime(std::string(format) + " ± " + format), e.mean, e.half_width);
}

// The shares of bodies with 0, 1, 2, ... contacts, pooled over the members.
std::string contact_distribution(const PileEnsemble& e) {
  std::map<int, std::size_t> counts;
  std::size_t bodies = 0;
  for (const PileMeasures& m : e.members) {
    for (const int c : m.contacts)
      ++counts[c];
    bodies += m.contacts.size();
  }
  std::string out;
  for (const auto& [c, n] : counts) {
    out += fmt::format("{}{}: {:.0f}%", out.empty() ? "" : ", ", c,
                       100.0 * static_cast<double>(n) / static_cast<double>(bodies));
  }
  return out;
}

struct Statistic {
  const char* name;
  const char* format;
  Estimate (PileEnsemble::*get)() const;
};

constexpr Statistic kStatistics[] = {
    {"settle time (s)", "{:.2f}", &PileEnsemble::settle_time},
    {"centre of mass height (m)", "{:.4f}", &PileEnsemble::com_height},
    {"packing fraction", "{:.4f}", &PileEnsemble::packing_fraction},
    {"contacts per body", "{:.2f}", &PileEnsemble::mean_contacts},
};

// The statistics on which `e`'s mean is farther from the finest's than a cheaper setting's
// (one listed before it for the same scene) by more than the two confidence intervals together:
// worse than that cheaper setting at 95% confidence, or "—".
std::string farther_than_cheaper(const std::vector<PileEnsemble>& ensembles, const PileEnsemble& e,
                                 const PileEnsemble& finest) {
  std::string out;
  for (const Statistic& s : kStatistics) {
    const Estimate mine = (e.*s.get)(), target = (finest.*s.get)();
    for (const PileEnsemble& cheaper : ensembles) {
      if (&cheaper == &e) break;
      if (cheaper.scene != e.scene) continue;
      const Estimate theirs = (cheaper.*s.get)();
      if (std::abs(mine.mean - target.mean) >
          std::abs(theirs.mean - target.mean) + mine.half_width + theirs.half_width) {
        out += fmt::format("{}{} (than {})", out.empty() ? "" : ", ", s.name, cheaper.setting);
        break;
      }
    }
  }
  return out.empty() ? "—" : out;
}

}  // namespace

void write_piles_csv(const std::filesystem::path& path,
                     const std::vector<PileEnsemble>& ensembles) {
  std::ofstream out(path);
  out << "scene,setting,member,settle_time,com_height,packing_fraction,mean_contacts,contacts\n";
  for (const PileEnsemble& e : ensembles) {
    for (std::size_t k = 0; k < e.members.size(); ++k) {
      const PileMeasures& m = e.members[k];
      std::string contacts;
      for (const int c : m.contacts)
        contacts += fmt::format("{}{}", contacts.empty() ? "" : " ", c);
      out << fmt::format("{},{},{},{:.6g},{:.9g},{:.6g},{:.6g},{}\n", e.scene, e.setting, k,
                         m.settle_time, m.com_height, m.packing_fraction, m.mean_contacts(),
                         contacts);
    }
  }
}

void write_piles_markdown(const std::filesystem::path& path,
                          const std::vector<PileEnsemble>& ensembles) {
  if (ensembles.empty()) return;
  std::ofstream out(path);
  out << fmt::format(
      "# The piles by statistics\n\n"
      "Written by `build/release/bench/accuracy_study docs/accuracy` (bench/pile_statistics.cpp). "
      "A pile is chaotic: two runs whose settings differ at all give two different piles within "
      "a second, so the piles are compared by what a user sees instead of by trajectory. Each "
      "setting runs an ensemble of {} piles whose movable bodies start moved by {:g} of their "
      "bounding radius in seeded random directions (the first as the scene is). Per run: the "
      "settle time (the first frame from which every body stays within {:g} of its radius, and "
      "{:g} rad, of where it ends), the height of the movable bodies' centre of mass at the end, "
      "their packing fraction (their area over their convex hull's) and the number of bodies "
      "within each one's contact bands at the end (from a detection of every pair, asleep or "
      "not). Estimates are means ± the half-width of their 95% confidence interval (Student's "
      "t); \"differs\" lists the statistics whose mean differs from the finest setting's by "
      "Welch's t-test at 95%, \"—\" where none does; the last column the statistics on which a "
      "setting is farther from the finest than a cheaper one by more than both confidence "
      "intervals together (worse at 95% confidence). finest: max_step 62.5 µs and the finest "
      "of every other knob, with converging_contacts 1 (the figure scenes' reference).\n",
      ensembles.front().members.size(), kEnsembleShare, kSettledShare, kSettledShare);
  std::vector<std::string> scenes;
  for (const PileEnsemble& e : ensembles) {
    if (std::find(scenes.begin(), scenes.end(), e.scene) == scenes.end()) scenes.push_back(e.scene);
  }
  for (const std::string& scene : scenes) {
    const PileEnsemble* finest = nullptr;
    for (const PileEnsemble& e : ensembles) {
      if (e.scene == scene && e.setting == "finest") finest = &e;
    }
    out << "\n## " << scene << "\n\n| setting | wall s (all runs) |";
    for (const Statistic& s : kStatistics)
      out << " " << s.name << " |";
    out << " contacts per body, share of bodies | differs from finest | farther from finest than "
           "a cheaper setting |\n|---|---|";
    for (std::size_t i = 0; i < std::size(kStatistics); ++i)
      out << "---|";
    out << "---|---|---|\n";
    for (const PileEnsemble& e : ensembles) {
      if (e.scene != scene) continue;
      out << fmt::format("| {} | {:.2f} |", e.setting, e.wall_s);
      std::string differs;
      for (const Statistic& s : kStatistics) {
        const Estimate estimate = (e.*s.get)();
        out << " " << format_estimate(estimate, s.format) << " |";
        if (finest != nullptr && &e != finest && e.members.size() > 1 &&
            means_differ(estimate, (finest->*s.get)())) {
          differs += fmt::format("{}{}", differs.empty() ? "" : ", ", s.name);
        }
      }
      out << " " << contact_distribution(e) << " | "
          << (&e == finest      ? ""
              : differs.empty() ? "—"
                                : differs)
          << " | "
          << (finest == nullptr || &e == finest ? "" : farther_than_cheaper(ensembles, e, *finest))
          << " |\n";
    }
  }
}

}  // namespace rugosim::study
