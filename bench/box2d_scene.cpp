// A validation scene run in Box2D, sampled as study::run_scene samples rugosim, and what the
// Box2D world was made of (masses, fixtures), in SI units.
#include "box2d_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "box2d_scene_world.h"
#include "engine/scene/scene_world.h"

namespace rugosim::bench {
namespace {

std::shared_ptr<const World> rugosim_world(const Scene& scene, const std::string& file) {
  SceneWorld built = build_world(scene, file);
  if (!built.world) throw std::runtime_error(file + ": the scene does not build");
  return std::shared_ptr<const World>(std::move(built.world));
}

Vec2 from_box2d(const b2Vec2& v, double scale) {
  return Vec2(static_cast<double>(v.x), static_cast<double>(v.y)) / scale;
}

BodyState state_of(const b2Body& body, double scale) {
  BodyState s;
  s.position = from_box2d(body.GetWorldCenter(), scale);
  s.angle = static_cast<double>(body.GetAngle());
  s.velocity = from_box2d(body.GetLinearVelocity(), scale);
  s.angular_velocity = static_cast<double>(body.GetAngularVelocity());
  return s;
}

}  // namespace

double suggested_length_scale(const World& world) {
  double size = 0.0;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    if (!world.body(i).fixed()) size = std::max(size, 2.0 * world.body(i).bounding_radius());
  }
  return size > 0.0 ? 1.0 / size : 1.0;
}

study::Run run_box2d_scene(const Scene& scene, const std::string& file,
                           const Box2dSceneOptions& options, int repeats) {
  const std::shared_ptr<const World> world = rugosim_world(scene, file);
  study::Run best;
  for (int r = 0; r < std::max(repeats, 1); ++r) {
    Box2dSceneWorld box2d = build_box2d_scene(scene, *world, options);
    study::Run run;
    run.fps = scene.render.fps;
    run.world = world;
    for (std::size_t i = 0; i < world->body_count(); ++i) {
      if (!world->body(i).fixed()) run.movers.push_back(i);
    }
    const auto dt = static_cast<float>(1.0 / options.hz);
    const auto velocity_iterations = static_cast<int32>(options.velocity_iterations);
    const auto position_iterations = static_cast<int32>(options.position_iterations);
    const auto last = static_cast<std::size_t>(std::floor(scene.duration * run.fps + 1e-9));
    long steps = 0;
    const auto begin = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k <= last; ++k) {
      // The last step not beyond frame time k/fps (the 1e-9 absorbs rounding when hz is a
      // multiple of fps, so that frames land on steps).
      const auto due =
          static_cast<long>(std::floor(static_cast<double>(k) / run.fps * options.hz + 1e-9));
      for (; steps < due; ++steps)
        box2d.world->Step(dt, velocity_iterations, position_iterations);
      std::vector<BodyState> states;
      for (const std::size_t i : run.movers)
        states.push_back(state_of(*box2d.bodies[i], box2d.scale));
      run.frames.push_back(std::move(states));
    }
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (r == 0 || run.wall_s < best.wall_s) best = std::move(run);
  }
  return best;
}

std::vector<Box2dMass> box2d_masses(const Scene& scene, const std::string& file,
                                    const Box2dSceneOptions& options) {
  const std::shared_ptr<const World> world = rugosim_world(scene, file);
  const Box2dSceneWorld box2d = build_box2d_scene(scene, *world, options);
  const double scale = box2d.scale;
  std::vector<Box2dMass> out;
  for (std::size_t i = 0; i < world->body_count(); ++i) {
    if (world->body(i).fixed()) continue;
    const b2Body& body = *box2d.bodies[i];
    const double mass = static_cast<double>(body.GetMass());
    // GetInertia() is about the body origin; the parallel-axis term moves it to the centre of
    // mass (the origin is the centre of mass here, so the term is float rounding).
    const Vec2 centre = from_box2d(body.GetLocalCenter(), 1.0);
    const double inertia = static_cast<double>(body.GetInertia()) - mass * centre.squaredNorm();
    // Masses are in kg at every scale; inertias carry length² of Box2D units.
    out.push_back({i, scene.bodies[i].name, mass, inertia / (scale * scale)});
  }
  return out;
}

std::vector<Box2dFixture> box2d_fixtures(const Scene& scene, const std::string& file,
                                         const Box2dSceneOptions& options) {
  const std::shared_ptr<const World> world = rugosim_world(scene, file);
  const Box2dSceneWorld box2d = build_box2d_scene(scene, *world, options);
  const double scale = box2d.scale;
  std::vector<Box2dFixture> out;
  for (std::size_t i = 0; i < box2d.bodies.size(); ++i) {
    const b2Body& body = *box2d.bodies[i];
    for (const b2Fixture* f = body.GetFixtureList(); f != nullptr; f = f->GetNext()) {
      Box2dFixture fixture;
      fixture.body = i;
      fixture.friction = static_cast<double>(f->GetFriction());
      fixture.restitution = static_cast<double>(f->GetRestitution());
      const auto world_point = [&](const b2Vec2& local) {
        return from_box2d(body.GetWorldPoint(local), scale);
      };
      const b2Shape* shape = f->GetShape();
      switch (shape->GetType()) {
        case b2Shape::e_circle:
          fixture.kind = "circle";
          fixture.radius = static_cast<double>(shape->m_radius) / scale;
          fixture.vertices.push_back(
              world_point(static_cast<const b2CircleShape*>(shape)->m_p));  // its centre
          break;
        case b2Shape::e_polygon: {
          fixture.kind = "polygon";
          const auto* polygon = static_cast<const b2PolygonShape*>(shape);
          for (int32 k = 0; k < polygon->m_count; ++k)
            fixture.vertices.push_back(world_point(polygon->m_vertices[k]));
          break;
        }
        default:
          fixture.kind = "other";
      }
      out.push_back(std::move(fixture));
    }
  }
  return out;
}

}  // namespace rugosim::bench
