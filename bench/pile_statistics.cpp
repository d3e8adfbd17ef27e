#include "pile_statistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/random.h"
#include "engine/scene/scene_world.h"

namespace rugosim::study {
namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Points per B-spline segment for the hull: a chord of a quarter segment stays within the
// curve's flatness of it, far below the bodies' size.
constexpr int kHullSamplesPerSegment = 8;

// Whether every mover of `frame` lies within kSettledShare of its place in `last`.
bool near_final(const std::vector<BodyState>& frame, const std::vector<BodyState>& last,
                const std::vector<double>& radius) {
  for (std::size_t m = 0; m < frame.size(); ++m) {
    if ((frame[m].position - last[m].position).norm() > kSettledShare * radius[m]) return false;
    if (std::abs(frame[m].angle - last[m].angle) > kSettledShare) return false;
  }
  return true;
}

template <typename Get>
Estimate estimate_of(const std::vector<PileMeasures>& members, Get get) {
  std::vector<double> samples;
  for (const PileMeasures& m : members)
    samples.push_back(get(m));
  return estimate(samples);
}

}  // namespace

double PileMeasures::mean_contacts() const {
  if (contacts.empty()) return 0.0;
  return static_cast<double>(std::accumulate(contacts.begin(), contacts.end(), 0)) /
         static_cast<double>(contacts.size());
}

double convex_hull_area(std::vector<Vec2> points) {
  if (points.size() < 3) return 0.0;
  std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  // Andrew's monotone chain: lower hull, then upper hull, counter-clockwise.
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0)
      --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], *it) <= 0.0)
      --k;
    hull[k++] = *it;
  }
  hull.resize(k - 1);  // the last point is the first
  double twice = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

PileMeasures measure_pile(const Run& run) {
  if (run.frames.empty() || run.movers.empty()) throw std::invalid_argument("an empty pile run");
  const World& world = *run.world;
  PileMeasures out;
  std::vector<double> radius;
  for (const std::size_t i : run.movers)
    radius.push_back(world.body(i).bounding_radius());

  const std::vector<BodyState>& last = run.frames.back();
  std::size_t settled = run.frames.size() - 1;
  while (settled > 0 && near_final(run.frames[settled - 1], last, radius))
    --settled;
  out.settle_time = static_cast<double>(settled) / run.fps;

  double mass = 0.0, moment = 0.0, area = 0.0;
  std::vector<Vec2> outline;
  for (const std::size_t i : run.movers) {
    const RigidBody& b = world.body(i);
    mass += b.mass();
    moment += b.mass() * b.state().position.y();
    area += b.area();
    for (std::size_t j = 0; j < b.curve().size(); ++j) {
      for (int s = 0; s < kHullSamplesPerSegment; ++s)
        outline.push_back(b.world_point(b.curve().point(j, s / double(kHullSamplesPerSegment))));
    }
  }
  out.com_height = moment / mass;
  out.packing_fraction = area / convex_hull_area(std::move(outline));

  // Every pair at the final state, asleep or not (the World's own manifolds skip pairs of
  // sleeping bodies, which it does not need to look at).
  std::vector<PlacedShape> placed(world.body_count());
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    placed[i].shape = &world.body(i).shape();
    placed[i].placement = world.body(i).placement();
    placed[i].fixed = world.body(i).fixed();
  }
  CollisionPipeline pipeline(world.settings().narrow_phase);
  std::vector<int> degree(world.body_count(), 0);
  for (const ContactManifold& m : pipeline.detect(placed)) {
    if (m.state() == PairState::kSeparated) continue;
    ++degree[m.body_a];
    ++degree[m.body_b];
  }
  for (const std::size_t i : run.movers)
    out.contacts.push_back(degree[i]);
  return out;
}

Scene perturbed_scene(const Scene& scene, const std::string& file, std::size_t member,
                      double share) {
  if (member == 0) return scene;
  SceneWorld built = build_world(scene, file);
  if (!built.world) throw std::runtime_error(file + ": the scene does not build");
  Scene out = scene;
  Rng rng(derive_seed(0x9113'0017u, member));
  for (std::size_t i = 0; i < out.bodies.size(); ++i) {
    if (out.bodies[i].fixed) continue;
    const double turn = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const double r = built.world->body(i).bounding_radius();
    out.bodies[i].position += share * r * Vec2(std::cos(turn), std::sin(turn));
  }
  return out;
}

double t975(double dof) {
  // Student's t at 0.975, dof 1 to 30.
  static constexpr std::array<double, 30> kTable = {
      12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (!(dof >= 1.0)) throw std::invalid_argument("t975 needs at least one degree of freedom");
  if (dof > 30.0) return 1.96;
  return kTable[static_cast<std::size_t>(std::floor(dof)) - 1];  // fewer dof: the wider bound
}

Estimate estimate(const std::vector<double>& samples) {
  Estimate e;
  e.n = samples.size();
  if (e.n == 0) return e;
  e.mean = std::accumulate(samples.begin(), samples.end(), 0.0) / static_cast<double>(e.n);
  if (e.n < 2) return e;
  double squares = 0.0;
  for (const double x : samples)
    squares += (x - e.mean) * (x - e.mean);
  e.sd = std::sqrt(squares / static_cast<double>(e.n - 1));
  e.half_width = t975(static_cast<double>(e.n - 1)) * e.sd / std::sqrt(static_cast<double>(e.n));
  return e;
}

bool means_differ(const Estimate& a, const Estimate& b) {
  if (a.n < 2 || b.n < 2) throw std::invalid_argument("a t-test needs two samples on each side");
  const double va = a.sd * a.sd / static_cast<double>(a.n);
  const double vb = b.sd * b.sd / static_cast<double>(b.n);
  if (va + vb == 0.0) return a.mean != b.mean;
  // Welch–Satterthwaite degrees of freedom.
  const double dof =
      (va + vb) * (va + vb) /
      (va * va / static_cast<double>(a.n - 1) + vb * vb / static_cast<double>(b.n - 1));
  return std::abs(a.mean - b.mean) / std::sqrt(va + vb) > t975(std::max(1.0, dof));
}

Estimate PileEnsemble::settle_time() const {
  return estimate_of(members, [](const PileMeasures& m) { return m.settle_time; });
}
Estimate PileEnsemble::com_height() const {
  return estimate_of(members, [](const PileMeasures& m) { return m.com_height; });
}
Estimate PileEnsemble::packing_fraction() const {
  return estimate_of(members, [](const PileMeasures& m) { return m.packing_fraction; });
}
Estimate PileEnsemble::mean_contacts() const {
  return estimate_of(members, [](const PileMeasures& m) { return m.mean_contacts(); });
}

PileEnsemble run_pile_ensemble(const std::string& name, const Scene& scene, const std::string& file,
                               const std::string& setting, const Accuracy& accuracy,
                               std::size_t members) {
  PileEnsemble e;
  e.scene = name;
  e.setting = setting;
  for (std::size_t k = 0; k < members; ++k) {
    const Run run = run_scene(perturbed_scene(scene, file, k, kEnsembleShare), file, accuracy, 1);
    e.wall_s += run.wall_s;
    e.members.push_back(measure_pile(run));
  }
  return e;
}

}  // namespace rugosim::study
