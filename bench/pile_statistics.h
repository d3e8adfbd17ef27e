// The chaotic piles by statistics (issue 17; docs/accuracy, "Piles"): a pile's trajectory
// diverges from any other run's within a second, so the study compares what a user sees and a
// physicist would check instead: when the pile settles, how high its centre of mass ends, how
// densely it packs, and how many neighbours each body rests on. Each setting runs an ensemble
// of piles whose initial states differ by 1e-9 of the body size; its statistics get 95%
// confidence intervals, and each setting's are tested against the finest setting's.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accuracy_metrics.h"
#include "engine/scene/scene.h"

namespace rugosim::study {

// What one run of a pile ends with.
struct PileMeasures {
  // s: the first frame time from which every body stays within kSettledShare of its bounding
  // radius (and kSettledShare rad of turn) of where it ends; the duration when the last frame
  // still moves.
  double settle_time = 0.0;
  double com_height = 0.0;        // m, the movable bodies' centre of mass, y, at the end
  double packing_fraction = 0.0;  // their area over the area of their convex hull, at the end
  // Per movable body, the number of bodies (fixed ones included) within its contact bands at
  // the end: the coordination numbers.
  std::vector<int> contacts;
  double mean_contacts() const;
};

inline constexpr double kSettledShare = 0.05;

// The area of the convex hull of `points` (m²); 0 for fewer than three.
double convex_hull_area(std::vector<Vec2> points);

// Measures a pile run; the contacts come from a detection of every pair at the final state
// (asleep bodies included).
PileMeasures measure_pile(const Run& run);

// `scene` with each movable body moved by `share` of its bounding radius in a direction drawn
// from `member` (member 0: the scene as it is). The same member always gives the same scene.
Scene perturbed_scene(const Scene& scene, const std::string& file, std::size_t member,
                      double share);

// Mean, sample standard deviation and the half-width of the 95% confidence interval of the
// mean (Student's t with n − 1 degrees of freedom).
struct Estimate {
  double mean = 0.0;
  double sd = 0.0;
  double half_width = 0.0;
  std::size_t n = 0;
};
Estimate estimate(const std::vector<double>& samples);

// Student's t quantile at 0.975 for `dof` degrees of freedom (dof >= 1; the normal 1.96 beyond
// the table).
double t975(double dof);

// Welch's two-sample t-test at 95%: whether the means of a and b differ. Two samples without
// spread differ exactly when their means do.
bool means_differ(const Estimate& a, const Estimate& b);

// One setting's ensemble of a pile scene.
struct PileEnsemble {
  std::string scene;
  std::string setting;  // "draft", "normal", "precise", "finest"
  std::vector<PileMeasures> members;
  double wall_s = 0.0;  // s, summed over the members
  Estimate settle_time() const;
  Estimate com_height() const;
  Estimate packing_fraction() const;
  Estimate mean_contacts() const;
};

// Runs `members` perturbed copies of `scene` (perturbed_scene, kEnsembleShare) at `accuracy`.
inline constexpr double kEnsembleShare = 1e-9;
PileEnsemble run_pile_ensemble(const std::string& name, const Scene& scene, const std::string& file,
                               const std::string& setting, const Accuracy& accuracy,
                               std::size_t members);

}  // namespace rugosim::study
