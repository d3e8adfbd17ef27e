#include "convergence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rugosim::study {

std::vector<double> convergence_steps() {
  return {8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5};
}

Accuracy finest_at(double step) {
  // The exact mid-step solve (soft_rest 0), not normal's soft one: the method's limit is the
  // paper's model with every tolerance tight, whose resting contact the soft springs
  // approximate.
  return Accuracy{.max_step = step,
                  .rest_stride = 1,
                  .mid_step_rest = 1,
                  .converging_contacts = 1,
                  .rest_sweeps = 1024,
                  .soft_rest = 0,
                  .toi_tolerance = 1e-11,
                  .max_bisections = 200,
                  .newton_tolerance = 1e-14,
                  .newton_iterations = 100,
                  .seed_depth = 60,
                  .contact_passes = 1024,
                  .contact_threshold = 1e-5};
}

StateSeries state_series(const Run& run) {
  StateSeries s;
  std::vector<double> radius;
  for (const std::size_t i : run.movers)
    radius.push_back(run.world->body(i).bounding_radius());
  for (const std::vector<BodyState>& frame : run.frames) {
    for (std::size_t m = 0; m < frame.size(); ++m) {
      const BodyState& b = frame[m];
      s.pose.insert(s.pose.end(),
                    {b.position.x() / radius[m], b.position.y() / radius[m], b.angle});
      s.velocity.insert(s.velocity.end(), {b.velocity.x() / radius[m], b.velocity.y() / radius[m],
                                           b.angular_velocity});
    }
  }
  return s;
}

namespace {

// Squared distances of the (x, y, angle) triples of two series, summed, and their count.
double pose_square_sum(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("two runs of different lengths");
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); i += 3) {
    const double dx = a[i] - b[i], dy = a[i + 1] - b[i + 1], da = a[i + 2] - b[i + 2];
    sum += dx * dx + dy * dy + da * da;
  }
  return sum;
}

}  // namespace

double pose_distance(const StateSeries& a, const StateSeries& b) {
  const std::size_t triples = a.pose.size() / 3;
  return triples > 0 ? std::sqrt(pose_square_sum(a.pose, b.pose) / static_cast<double>(triples))
                     : 0.0;
}

StateSeries richardson_limit(const StateSeries& x4h, const StateSeries& x2h, const StateSeries& xh,
                             double* order) {
  const double coarse = std::sqrt(pose_square_sum(x4h.pose, x2h.pose));
  const double fine = std::sqrt(pose_square_sum(x2h.pose, xh.pose));
  // Runs that agree to rounding have no order to measure; first order is then the cautious
  // guess (it moves the limit furthest from the finest run).
  double p = (fine > 0.0 && coarse > 0.0) ? std::log2(coarse / fine) : 1.0;
  p = std::clamp(p, 0.5, 4.0);
  if (order != nullptr) *order = p;
  const double scale = 1.0 / (std::exp2(p) - 1.0);
  StateSeries limit = xh;
  for (std::size_t i = 0; i < limit.pose.size(); ++i)
    limit.pose[i] += (xh.pose[i] - x2h.pose[i]) * scale;
  for (std::size_t i = 0; i < limit.velocity.size(); ++i)
    limit.velocity[i] += (xh.velocity[i] - x2h.velocity[i]) * scale;
  return limit;
}

Run run_from_series(const StateSeries& limit, const Run& like) {
  Run out;
  out.movers = like.movers;
  out.fps = like.fps;
  out.world = like.world;
  out.stats = like.stats;
  std::size_t i = 0;
  for (const std::vector<BodyState>& frame : like.frames) {
    std::vector<BodyState> states;
    for (std::size_t m = 0; m < frame.size(); ++m, i += 3) {
      const double r = like.world->body(like.movers[m]).bounding_radius();
      BodyState b;
      b.position = Vec2(limit.pose[i] * r, limit.pose[i + 1] * r);
      b.angle = limit.pose[i + 2];
      b.velocity = Vec2(limit.velocity[i] * r, limit.velocity[i + 1] * r);
      b.angular_velocity = limit.velocity[i + 2];
      states.push_back(b);
    }
    out.frames.push_back(std::move(states));
  }
  return out;
}

double observed_order(const std::vector<double>& steps, const std::vector<double>& errors,
                      double lo, double hi) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    // Relative slack so that 1.25e-4 given as 0.000125 still counts.
    if (steps[i] > hi * (1 + 1e-9) || steps[i] < lo * (1 - 1e-9) || !(errors[i] > kNoiseFloor))
      continue;
    const double x = std::log(steps[i]), y = std::log(errors[i]);
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  return n >= 3.0 && denominator > 0.0 ? (n * sxy - sx * sy) / denominator
                                       : std::numeric_limits<double>::quiet_NaN();
}

bool decreases_monotonically(const std::vector<double>& errors, double tolerance, int* first_rise) {
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double before = std::max(errors[i - 1], kNoiseFloor);
    if (std::max(errors[i], kNoiseFloor) > before * (1.0 + tolerance)) {
      if (first_rise != nullptr) *first_rise = static_cast<int>(i);
      return false;
    }
  }
  if (first_rise != nullptr) *first_rise = -1;
  return true;
}

SceneConvergence study_convergence(const std::string& name, const Scene& scene,
                                   const std::string& file, const std::vector<double>& steps,
                                   int repeats) {
  if (steps.size() < 3) throw std::invalid_argument("a convergence study needs three steps");
  SceneConvergence out;
  out.name = name;
  std::vector<Run> runs;
  std::vector<StateSeries> series;
  for (const double step : steps) {
    runs.push_back(run_scene(scene, file, finest_at(step), repeats));
    series.push_back(state_series(runs.back()));
  }
  const std::size_t n = steps.size();
  const StateSeries limit =
      richardson_limit(series[n - 3], series[n - 2], series[n - 1], &out.richardson_order);
  std::vector<double> errors;
  for (std::size_t i = 0; i < n; ++i) {
    ConvergencePoint p;
    p.step = steps[i];
    p.wall_s = runs[i].wall_s;
    p.error = pose_distance(series[i], limit);
    p.previous = i > 0 ? pose_distance(series[i], series[i - 1]) : 0.0;
    p.closed = closed_form_error(name, scene, runs[i]);
    p.stats = runs[i].stats;
    errors.push_back(p.error);
    out.points.push_back(std::move(p));
  }
  out.order = observed_order(steps, errors, kOrderTo, kOrderFrom);
  out.monotone = decreases_monotonically(errors, kMonotoneTolerance, &out.first_rise);
  out.floor = closed_form_error(name, scene, run_from_series(limit, runs.back()));
  return out;
}

}  // namespace rugosim::study
