#include "engine/scene/scene_world.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/random.h"
#include "engine/dynamics/containment.h"
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
    case ShapeKind::kPolygon:
      return polygon_control_points(shape.control_points, shape.rounding, shape.segments);
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

// Pairs (inner, outer) of bodies whose boundaries do not cross (`crossing` lists those that
// do) and where the inner one lies inside the outer one's curve (containment.h).
std::vector<std::pair<std::size_t, std::size_t>> nested_pairs(
    const World& world, const std::vector<std::pair<std::size_t, std::size_t>>& crossing) {
  std::vector<ContainmentSamples> sampled;
  for (std::size_t i = 0; i < world.body_count(); ++i)
    sampled.push_back(containment_samples(world.body(i)));
  std::vector<std::pair<std::size_t, std::size_t>> nested;
  for (std::size_t inner = 0; inner < sampled.size(); ++inner) {
    for (std::size_t outer = 0; outer < sampled.size(); ++outer) {
      if (inner == outer) continue;
      const std::pair<std::size_t, std::size_t> key{std::min(inner, outer), std::max(inner, outer)};
      if (std::find(crossing.begin(), crossing.end(), key) != crossing.end()) continue;
      if (lies_inside(world.body(inner), sampled[inner], world.body(outer), sampled[outer])
              .value_or(false)) {
        nested.emplace_back(inner, outer);
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
