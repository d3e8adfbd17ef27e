// Convergence with the step (issue 17; docs/accuracy, "Convergence with the step"): a scene run
// at a sequence of max_steps, each halving the last, with every other knob at its finest; the
// method's own limit estimated by Richardson extrapolation of the three finest runs; each run's
// distance from that limit, the observed order of convergence, and, for a scene with a closed
// form, the limit's distance from it (the model's floor, which no step removes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "accuracy_metrics.h"

namespace rugosim::study {

// The steps of the study, coarsest first: 8, 4, 2, 1, 0.5, 0.25, 0.125 and 0.0625 ms.
std::vector<double> convergence_steps();

// The finest setting of every knob but the step (the accuracy study's reference), at `step`.
Accuracy finest_at(double step);

// A Run's states as one vector, frame by frame and mover by mover: x/r, y/r and the angle (so
// that each is in body radii, r the body's bounding radius), then the velocities over the
// same scales (vx/r, vy/r in 1/s, ω). Two runs of a scene give vectors of the same layout.
struct StateSeries {
  std::vector<double> pose;      // 3 per mover per frame, in body radii
  std::vector<double> velocity;  // 3 per mover per frame, in body radii per second
};
StateSeries state_series(const Run& run);

// RMS over frames and movers of the distance of two pose series, in body radii (each mover's
// position and its angle times 1, that is the arc its boundary turns through per radius).
double pose_distance(const StateSeries& a, const StateSeries& b);

// Richardson extrapolation of three runs at steps 4h, 2h and h, element by element, with the
// order p taken from the runs themselves: p = log2(|x_4h − x_2h| / |x_2h − x_h|) over the whole
// pose series, kept within [0.5, 4]. `order` receives p.
StateSeries richardson_limit(const StateSeries& x4h, const StateSeries& x2h, const StateSeries& xh,
                             double* order);

// A Run whose states are `limit`'s (the layout of `like`), so that the closed forms can be
// measured on the limit.
Run run_from_series(const StateSeries& limit, const Run& like);

// Errors at or below this many body radii are below what the step can be asked to resolve:
// the solvers stop at tolerances of their own (the mid-step solve when no contact velocity
// changes by more than 1e-6·|g|·h in a sweep; a stick or a slip decided on either side of that
// at the sliding disk's rolling transition moves it 7e-8 m, 3.5e-7 radii, for the rest of the
// run). Two such errors are equal whatever their ratio, and a run that close is converged.
inline constexpr double kNoiseFloor = 1e-6;

// The least-squares slope of log(error) against log(step) over the points with steps in
// [lo, hi] and an error above kNoiseFloor: the observed order of convergence. NaN where
// fewer than three points qualify (a scene converged at those steps: two points make a slope
// of whatever the first drop into the noise was).
double observed_order(const std::vector<double>& steps, const std::vector<double>& errors,
                      double lo, double hi);

// Whether the errors, coarsest step first, never grow by more than `tolerance` (a share) from
// one step to the next finer one, errors below kNoiseFloor counted as kNoiseFloor;
// `first_rise` receives the index of the first point that does (or -1).
bool decreases_monotonically(const std::vector<double>& errors, double tolerance,
                             int* first_rise = nullptr);

// One step's run of a scene.
struct ConvergencePoint {
  double step = 0.0;      // s
  double wall_s = 0.0;    // s, the simulation alone
  double error = 0.0;     // RMS pose distance from the limit, in body radii
  double previous = 0.0;  // RMS pose distance from the run at twice the step (0 for the first)
  std::optional<ClosedFormError> closed;  // validation scenes
  StepStats stats;
};

struct SceneConvergence {
  std::string name;
  std::vector<ConvergencePoint> points;  // coarsest first
  double richardson_order = 0.0;         // p of the extrapolation
  double order = 0.0;                    // observed, 4 ms to 0.125 ms (NaN: converged there)
  bool monotone = false;                 // within kMonotoneTolerance
  int first_rise = -1;                   // index into points, or -1
  std::optional<ClosedFormError> floor;  // the limit against the closed form
};

// Noise allowed in the monotonicity check: an error may exceed the coarser step's by this share.
inline constexpr double kMonotoneTolerance = 0.10;
// The range of steps over which the observed order is fitted, s.
inline constexpr double kOrderFrom = 4e-3;
inline constexpr double kOrderTo = 1.25e-4;

// Runs `scene` at each of `steps` (at least three, each half the last) and measures its
// convergence; `repeats` timed runs per step, the fastest kept.
SceneConvergence study_convergence(const std::string& name, const Scene& scene,
                                   const std::string& file, const std::vector<double>& steps,
                                   int repeats);

}  // namespace rugosim::study
