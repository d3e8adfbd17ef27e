// The closed forms of the validation scenes (scenes/validation_*.json), each computed from the
// scene's own numbers (speeds, σ, λ_min, friction gain, gravity, restitution), never from a
// run.
#include "accuracy_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "engine/scene/scene_world.h"

namespace rugosim::study {
namespace {

std::size_t first_fixed(const World& world) {
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    if (world.body(i).fixed()) return i;
  }
  throw std::invalid_argument("the scene has no fixed body");
}

// μ of a homogeneous surface, μ = k·max(0, λ − λ_min) (paper §4.2).
double surface_mu(const World& world, std::size_t body, std::size_t segment = 0) {
  const RigidBody& b = world.body(body);
  const double lambda = b.shape().tolerances().segment_tolerance(segment);
  return world.settings().friction_gain * std::max(0.0, lambda - b.material().lambda_min);
}

double frame_time(const Run& run, std::size_t k) {
  return static_cast<double>(k) / run.fps;
}

// Slides as x0 + v0·t − ½μg·t² until t* = v0 / (3μg), then rolls at 2v0/3 (I = ½mr²).
// Positions, not sampled velocities: a body in resting contact hops inside its band, and each
// micro-collision's friction kicks vx a little, which a frame may catch at any phase. The
// parts: the largest distance from the sliding parabola over the frames before 0.9 t*,
// relative to the distance slid by t*, and the mean speed over the last quarter second,
// relative to 2v0/3.
ClosedFormError sliding_disk(const Run& run) {
  const World& world = *run.world;
  const double mu = surface_mu(world, first_fixed(world));
  const double g = world.settings().gravity.norm();
  const double v0 = run.frames.front()[0].velocity.x();
  const double x0 = run.frames.front()[0].position.x();
  const double t_star = v0 / (3.0 * mu * g);
  const double slid = v0 * t_star - 0.5 * mu * g * t_star * t_star;
  double slide = 0.0;
  for (std::size_t k = 0; k < run.frames.size() && frame_time(run, k) < 0.9 * t_star; ++k) {
    const double t = frame_time(run, k);
    const double exact = x0 + v0 * t - 0.5 * mu * g * t * t;
    slide = std::max(slide, std::abs(run.frames[k][0].position.x() - exact) / slid);
  }
  const std::size_t last = run.frames.size() - 1;
  const auto back = std::min(
      last, std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(0.25 * run.fps))));
  const double speed =
      (run.frames[last][0].position.x() - run.frames[last - back][0].position.x()) /
      (frame_time(run, last) - frame_time(run, last - back));
  const double rolling = 2.0 * v0 / 3.0;
  const double roll = std::abs(speed - rolling) / rolling;
  return {std::max(slide, roll),
          "max(|x − (x0 + v0·t − ½μg·t²)| / distance slid, |mean final speed − 2v0/3| / (2v0/3))",
          {{"sliding distance", slide}, {"rolling speed", roll}}};
}

// Slides down the slope (+x, gravity tilted) at a = g_x − μ·(−g_y): a from a least-squares
// parabola through x(t) over t >= 0.2 s (after the release hop; positions, for the reason
// given above), relative to a.
ClosedFormError incline_above(const Run& run) {
  const World& world = *run.world;
  const double mu = surface_mu(world, first_fixed(world));
  const Vec2 g = world.settings().gravity;
  const double a = g.x() + mu * g.y();
  // Normal equations of x = c0 + c1·t + c2·t², t centred on the window for conditioning.
  std::vector<double> ts, xs;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    if (frame_time(run, k) < 0.2) continue;
    ts.push_back(frame_time(run, k));
    xs.push_back(run.frames[k][0].position.x());
  }
  double mean_t = 0.0;
  for (const double t : ts)
    mean_t += t / static_cast<double>(ts.size());
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double u = ts[i] - mean_t;
    const Eigen::Vector3d basis(1.0, u, u * u);
    m += basis * basis.transpose();
    r += basis * xs[i];
  }
  const double fitted = 2.0 * m.ldlt().solve(r)(2);
  const double e = std::abs(fitted - a) / a;
  return {e, "|a of the parabola through x(t) − g(sin θ − μ cos θ)| / that", {{"acceleration", e}}};
}

// Below the friction angle the block stays: how far it moved after the release hop (t >= 0.2
// s), as a share of the distance it would slide without friction over that time.
ClosedFormError incline_below(const Run& run) {
  const World& world = *run.world;
  const Vec2 g = world.settings().gravity;
  std::size_t from = 0;
  while (from + 1 < run.frames.size() && frame_time(run, from) < 0.2)
    ++from;
  const double t = frame_time(run, run.frames.size() - 1) - frame_time(run, from);
  const double moved = (run.frames.back()[0].position - run.frames[from][0].position).norm();
  const double e = moved / (0.5 * std::abs(g.x()) * t * t);
  return {e, "distance moved after 0.2 s / frictionless slide distance", {{"creep", e}}};
}

// Each apex is ε² of the one before. The apex height of a frame in flight is exact from its
// energy, y − r − top + vy²/(2g); a flight's value is the median over its frames, and the error
// the largest of |h_k / h_{k−1} − ε²| / ε² over the first three bounces.
ClosedFormError bouncing_disk(const Run& run, const Scene& scene) {
  const World& world = *run.world;
  const std::size_t floor_index = first_fixed(world);
  const BodySpec& floor = scene.bodies[floor_index];
  const double top = floor.position.y() + 0.5 * floor.shape.size.y();
  const BodySpec& disk = scene.bodies[run.movers[0]];
  const double r = disk.shape.radius;
  const double epsilon = std::max(floor.material.restitution, disk.material.restitution);
  const double g = world.settings().gravity.norm();
  std::vector<std::vector<double>> flights(1);
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    const BodyState& s = run.frames[k][0];
    if (k > 0 && run.frames[k - 1][0].velocity.y() <= 0.0 && s.velocity.y() > 0.0) {
      flights.emplace_back();  // bounced since the last frame
    }
    const double height = s.position.y() - r - top;
    if (height > 1e-4 * r) {
      flights.back().push_back(height + s.velocity.y() * s.velocity.y() / (2.0 * g));
    }
  }
  std::vector<double> apex;
  for (std::vector<double>& f : flights) {
    if (f.empty()) break;
    std::sort(f.begin(), f.end());
    apex.push_back(f[f.size() / 2]);
  }
  double worst = 0.0;
  const double expected = epsilon * epsilon;
  for (std::size_t k = 1; k <= 3; ++k) {
    // A bounce that did not happen has the ratio 0: an error of 1.
    const double ratio = k < apex.size() ? apex[k] / apex[k - 1] : 0.0;
    worst = std::max(worst, std::abs(ratio - expected) / expected);
  }
  return {worst, "max over 3 bounces |h_k / h_{k−1} − ε²| / ε²", {{"bounce ratio", worst}}};
}

// Two free disks collide head-on (no gravity): momentum is kept and the closing speed reversed
// by ε, so each one's velocity after the impact is known from the masses and the velocities
// before (the World's masses, of the B-spline outlines). The parts: each disk's velocity along
// the line of centres in the last frame, its error relative to the closing speed.
ClosedFormError two_disks(const Run& run, const Scene& scene) {
  const World& world = *run.world;
  const std::size_t a = run.movers.at(0), b = run.movers.at(1);
  const double ma = world.body(a).mass(), mb = world.body(b).mass();
  const double epsilon =
      std::max(scene.bodies[a].material.restitution, scene.bodies[b].material.restitution);
  const Vec2 line = (run.frames.front()[1].position - run.frames.front()[0].position).normalized();
  const double va = run.frames.front()[0].velocity.dot(line);
  const double vb = run.frames.front()[1].velocity.dot(line);
  const double momentum = ma * va + mb * vb;
  const double closing = va - vb;
  const double va_after = (momentum - mb * epsilon * closing) / (ma + mb);
  const double vb_after = (momentum + ma * epsilon * closing) / (ma + mb);
  const double ea = std::abs(run.frames.back()[0].velocity.dot(line) - va_after) / closing;
  const double eb = std::abs(run.frames.back()[1].velocity.dot(line) - vb_after) / closing;
  return {std::max(ea, eb),
          "max over both disks |v after − (momentum ∓ m_other·ε·closing) / (m_a + m_b)| / closing "
          "speed",
          {{"first disk's velocity", ea}, {"second disk's velocity", eb}}};
}

// A block at v0 reaches a patch of friction μ and, with its weight spread evenly over its base,
// its centre stops d = v0² / (2gμ) past the patch's start (the start taken from the floor's σ:
// the leftmost point of a rough segment). The model is approximate: a decelerating block
// leans on its front corner.
ClosedFormError rough_patch(const Run& run) {
  const World& world = *run.world;
  const std::size_t floor = first_fixed(world);
  const RigidBody& body = world.body(floor);
  double start = std::numeric_limits<double>::infinity();
  double mu = 0.0;
  for (std::size_t j = 0; j < body.curve().size(); ++j) {
    if (body.shape().tolerances().segment_tolerance(j) <= 0.0) continue;
    mu = std::max(mu, surface_mu(world, floor, j));
    for (int i = 0; i <= 8; ++i) {
      start = std::min(start, body.world_point(body.curve().segment(j).point(i / 8.0)).x());
    }
  }
  if (!(mu > 0.0)) throw std::invalid_argument("the rough patch has no friction");
  const double v0 = run.frames.front()[0].velocity.x();
  const double d = v0 * v0 / (2.0 * world.settings().gravity.norm() * mu);
  const double stop = run.frames.back()[0].position.x();
  const double e = std::abs(stop - (start + d)) / d;
  return {e, "|centre's stop − (patch start + v0²/2gμ)| / d", {{"stopping distance", e}}};
}

}  // namespace

Run run_scene(const Scene& scene, const std::string& file, const Accuracy& accuracy, int repeats) {
  Scene tuned = scene;
  tuned.accuracy = AccuracySpec{"normal", {}};
  for (const AccuracyKnob& knob : accuracy_knobs())
    tuned.accuracy.knobs[std::string(knob.key)] = knob.get(accuracy);
  Run best;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    SceneWorld built = build_world(tuned, file);
    if (!built.world) throw std::runtime_error(file + ": the scene does not build");
    std::shared_ptr<World> world = std::move(built.world);
    Run run;
    run.fps = scene.render.fps;
    for (std::size_t i = 0; i < world->body_count(); ++i) {
      if (!world->body(i).fixed()) run.movers.push_back(i);
    }
    const auto last = static_cast<std::size_t>(std::floor(scene.duration * run.fps + 1e-9));
    const auto begin = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k <= last; ++k) {
      if (k > 0) world->advance_to(static_cast<double>(k) / run.fps);
      world->clear_events();
      std::vector<BodyState> states;
      for (const std::size_t i : run.movers)
        states.push_back(world->body(i).state());
      run.frames.push_back(std::move(states));
    }
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    run.stats = world->stats();
    run.world = world;
    if (r == 0 || run.wall_s < best.wall_s) best = std::move(run);
  }
  return best;
}

std::optional<ClosedFormError> closed_form_error(const std::string& name, const Scene& scene,
                                                 const Run& run) {
  if (name == "validation_sliding_disk") return sliding_disk(run);
  if (name == "validation_incline_above") return incline_above(run);
  if (name == "validation_incline_below") return incline_below(run);
  if (name == "validation_bouncing_disk") return bouncing_disk(run, scene);
  if (name == "validation_rough_patch") return rough_patch(run);
  if (name == "validation_two_disks") return two_disks(run, scene);
  return std::nullopt;
}

double trajectory_error(const Run& run, const Run& reference) {
  const std::size_t frames = std::min(run.frames.size(), reference.frames.size());
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 0; k < frames; ++k) {
    for (std::size_t m = 0; m < run.movers.size(); ++m) {
      const double radius = run.world->body(run.movers[m]).bounding_radius();
      const double d =
          (run.frames[k][m].position - reference.frames[k][m].position).norm() / radius;
      sum += d * d;
      ++count;
    }
  }
  return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
}

}  // namespace rugosim::study
