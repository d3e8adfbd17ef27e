#include "engine/scene/scene_world.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/aabb.h"
#include "engine/core/random.h"
#include "engine/dynamics/overlap_depth.h"
#include "engine/geometry/shapes.h"
#include "engine/scene/model_limits.h"

namespace rugosim {
namespace {

std::vector<Vec2> control_points(const ShapeSpec& shape) {
  switch (shape.kind) {
    case ShapeKind::kCircle:
      return circle_control_points(shape.radius, shape.segments);
    case ShapeKind::kEllipse:
      return ellipse_control_points(shape.radii.x(), shape.radii.y(), shape.segments);
    case ShapeKind::kBox:
      return box_control_points(shape.size.x(), shape.size.y(), shape.segments);
    case ShapeKind::kBlob:
      return blob_control_points(shape.radius, shape.irregularity, shape.segments, shape.seed);
    case ShapeKind::kControlPoints:
      break;
  }
  return shape.control_points;
}

std::vector<double> sigmas(const Scene& scene, const BodySpec& body, std::size_t index,
                           std::size_t segments) {
  const RugositySpec& r = body.rugosity;
  if (r.pattern) {
    // Each body's random pattern (type_3) gets its own stream of the scene's seed.
    return pattern_sigmas(*r.pattern, r.sigma.empty() ? 0.0 : r.sigma.front(), segments,
                          derive_seed(scene.seed, index));
  }
  if (r.sigma.size() == 1) return std::vector<double>(segments, r.sigma.front());
  return r.sigma;  // one per segment, or empty for σ = 0
}

std::string body_path(std::size_t i) {
  return "/bodies/" + std::to_string(i);
}

}  // namespace

Accuracy scene_accuracy(const Scene& scene) {
  std::optional<Accuracy> accuracy = accuracy_preset(scene.accuracy.preset);
  if (!accuracy) {
    throw std::invalid_argument("unknown accuracy preset \"" + scene.accuracy.preset + "\"");
  }
  for (const auto& [key, value] : scene.accuracy.knobs) {
    const AccuracyKnob* knob = find_accuracy_knob(key);
    if (knob == nullptr) throw std::invalid_argument("unknown accuracy knob \"" + key + "\"");
    knob->set(*accuracy, value);
  }
  return *accuracy;
}

WorldSettings world_settings(const Scene& scene) {
  WorldSettings settings;
  settings.gravity = scene.gravity;
  settings.friction_gain = scene.friction_gain;
  return with_accuracy(settings, scene_accuracy(scene));
}

std::vector<RigidBodyDesc> body_descriptions(const Scene& scene) {
  std::vector<RigidBodyDesc> descs;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodySpec& body = scene.bodies[i];
    RigidBodyDesc desc;
    desc.control_points = control_points(body.shape);
    desc.sigma = sigmas(scene, body, i, desc.control_points.size());
    desc.q = scene.q;
    desc.material = body.material;
    desc.fixed = body.fixed;
    desc.position = body.position;
    desc.angle = body.angle;
    desc.velocity = body.velocity;
    desc.angular_velocity = body.angular_velocity;
    descs.push_back(std::move(desc));
  }
  return descs;
}

namespace {

// A body's boundary sampled for the containment test, and how far the sampled polygon may
// stray from the curve: a point farther than `tolerance` from the polygon is on the same side
// of the curve as of the polygon.
struct SampledBody {
  std::vector<Vec2> polygon;
  double tolerance = 0.0;  // m
  Aabb box;
};

constexpr int kContainmentSamples = 16;  // per segment

SampledBody sample_body(const RigidBody& body) {
  SampledBody s;
  s.polygon = sampled_boundary(body, kContainmentSamples);
  const PeriodicBSpline& curve = body.curve();
  double stray = 0.0;
  const auto per_segment = static_cast<std::size_t>(kContainmentSamples);
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (std::size_t k = 0; k < per_segment; ++k) {
      // The curve between two samples against the chord: its middle is the farthest, closely
      // enough for the cubic pieces between samples 1/16 of a segment apart (doubled below).
      const Vec2 u = s.polygon[j * per_segment + k];
      const Vec2 v = s.polygon[(j * per_segment + k + 1) % s.polygon.size()];
      const double t = (static_cast<double>(k) + 0.5) / kContainmentSamples;
      const Vec2 mid = body.world_point(curve.point(j, t));
      stray = std::max(stray, (mid - 0.5 * (u + v)).norm());
    }
  }
  s.tolerance = 2.0 * stray + 1e-12 * body.bounding_radius();
  for (const Vec2& p : s.polygon)
    s.box.extend(p);
  return s;
}

// The sampled boxes stray from the curves' by up to the tolerances: compared with that slack.
bool box_within(const Aabb& inner, const Aabb& outer, double slack) {
  return inner.min.x() >= outer.min.x() - slack && inner.min.y() >= outer.min.y() - slack &&
         inner.max.x() <= outer.max.x() + slack && inner.max.y() <= outer.max.y() + slack;
}

// Pairs (inner, outer) of bodies whose boundaries do not cross (`crossing` lists those that
// do) and where the inner one lies inside the outer one's curve.
std::vector<std::pair<std::size_t, std::size_t>> nested_pairs(
    const World& world, const std::vector<std::pair<std::size_t, std::size_t>>& crossing) {
  std::vector<SampledBody> sampled;
  for (std::size_t i = 0; i < world.body_count(); ++i)
    sampled.push_back(sample_body(world.body(i)));
  std::vector<std::pair<std::size_t, std::size_t>> nested;
  for (std::size_t inner = 0; inner < sampled.size(); ++inner) {
    for (std::size_t outer = 0; outer < sampled.size(); ++outer) {
      if (inner == outer) continue;
      const double slack = sampled[inner].tolerance + sampled[outer].tolerance;
      if (!box_within(sampled[inner].box, sampled[outer].box, slack)) continue;
      const std::pair<std::size_t, std::size_t> key{std::min(inner, outer), std::max(inner, outer)};
      if (std::find(crossing.begin(), crossing.end(), key) != crossing.end()) continue;
      // Any point of the inner boundary far enough from the outer polygon decides: the
      // boundaries do not cross, so all of it is on one side.
      for (const Vec2& p : sampled[inner].polygon) {
        if (distance_to_polygon(sampled[outer].polygon, p) <= sampled[outer].tolerance) continue;
        if (inside_polygon(sampled[outer].polygon, p)) nested.emplace_back(inner, outer);
        break;
      }
    }
  }
  return nested;
}

}  // namespace

SceneWorld build_world(const Scene& scene, const std::string& file, int threads) {
  SceneWorld out;
  WorldSettings settings = world_settings(scene);
  settings.threads = threads;
  auto world = std::make_unique<World>(settings);
  const std::vector<RigidBodyDesc> descs = body_descriptions(scene);
  for (std::size_t i = 0; i < descs.size(); ++i) {
    try {
      world->add_body(RigidBody(descs[i]), scene.bodies[i].name);
    } catch (const std::invalid_argument& e) {
      out.errors.push_back({file, body_path(i) + "/shape", e.what(), 0, 0});
    }
  }
  if (!out.errors.empty()) return out;
  out.errors = check_model_limits(*world, scene, file);
  if (!out.errors.empty()) return out;

  std::vector<PlacedShape> placed;
  for (std::size_t i = 0; i < world->body_count(); ++i) {
    placed.push_back(
        {&world->body(i).shape(), world->body(i).placement(), world->body(i).fixed(), false});
  }
  CollisionPipeline pipeline;
  std::vector<std::pair<std::size_t, std::size_t>> crossing;
  for (const ContactManifold& m : pipeline.detect(placed)) {
    if (m.state() != PairState::kIntersecting) continue;
    crossing.emplace_back(std::min(m.body_a, m.body_b), std::max(m.body_a, m.body_b));
    const Vec2 p = m.intersections.front().point;
    char where[96];
    std::snprintf(where, sizeof where, "(%.6g, %.6g)", p.x(), p.y());
    out.errors.push_back({file, body_path(m.body_a),
                          "body \"" + world->name(m.body_a) + "\" crosses body \"" +
                              world->name(m.body_b) + "\" (" + body_path(m.body_b) +
                              ") at t = 0, near " + where + "; expected bodies apart",
                          0, 0});
  }
  // Boundaries that do not cross can still enclose one another: a body wholly inside another
  // is no contact the engine could resolve (it would fall through the outer body's inside).
  for (const auto& [inner, outer] : nested_pairs(*world, crossing)) {
    out.errors.push_back({file, body_path(inner),
                          "body \"" + world->name(inner) + "\" lies wholly inside body \"" +
                              world->name(outer) + "\" (" + body_path(outer) +
                              ") at t = 0; expected bodies apart",
                          0, 0});
  }
  if (out.errors.empty()) out.world = std::move(world);
  return out;
}

}  // namespace rugosim
