// The pile scene (tests/support/pile_scene.h) built in Box2D 2.4.1, our main speed competitor,
// so that the benchmarks can compare wall times on the same scene, as the issue asks. Box2D has
// no curved shapes: each body becomes one b2Body whose fixtures are a compound of convex
// polygons (at most b2_maxPolygonVertices = 8 vertices each) approximating the same B-spline
// outline, with the same density, placement and velocities.
//
// Box2D is included by the .cpp only (b2World is forward-declared here), so code that includes
// this header needs neither Box2D's include path nor its float-heavy headers.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "support/pile_scene.h"

class b2World;

namespace rugosim::bench {

struct Box2dPileOptions {
  double friction;              // μ of every fixture (Box2D mixes sqrt(μa·μb), so μ it is)
  double restitution;           // ε of every fixture (Box2D mixes max(εa, εb), so ε it is)
  int velocity_iterations = 8;  // Box2D's recommended values
  int position_iterations = 3;
  // Outline points per B-spline segment, >= 1. Box2D's cost grows with the fixtures per body
  // (b2ContactManager::AddPair walks a body's whole contact list), and the pile's concave blobs
  // need a piece per concave edge, so this trades Box2D's speed against the outline's fidelity.
  int samples_per_segment = 4;
  // Box2D lengths per metre, > 0. Box2D's tolerances are absolute (a 0.1 m fat-AABB margin, a
  // 1 cm polygon skin, 5 mm slop), tuned for bodies of 0.1 to 10 m, while the pile's bodies
  // are 0.1 m in radius. A scale L builds the same scene in units of 1/L m (lengths and
  // velocities ×L, gravity ×L, Box2D's 1 m/s restitution threshold ×L, density /L² so masses
  // stay the same); the queries below answer in SI units whatever L.
  double length_scale = 1.0;
};

class Box2dPile {
 public:
  // Builds the world with gravity (0, −9.81) m/s² and one body per scene entry, fixed entries
  // static. Throws std::invalid_argument on bad options or (from RigidBody) a bad description,
  // and std::runtime_error when an outline cannot be cut into convex pieces Box2D accepts.
  Box2dPile(const std::vector<rugosim::testing::PileBody>& scene, const Box2dPileOptions& options);
  ~Box2dPile();
  Box2dPile(Box2dPile&&) noexcept;
  Box2dPile& operator=(Box2dPile&&) noexcept;

  // One b2World::Step of dt seconds with the options' iteration counts.
  void step(double dt);

  std::size_t body_count() const;     // every body, the static walls included
  std::size_t fixture_count() const;  // convex pieces over all bodies, walls included
  std::size_t awake_bodies() const;   // dynamic bodies that Box2D has not put to sleep
  // J per unit thickness: Σ ½mv² + ½Iω² over the dynamic bodies, I about the centre of mass.
  double kinetic_energy() const;
  // kg: Σ of the dynamic bodies' masses as Box2D computed them from the pieces.
  double dynamic_mass() const;
  // m: the largest y of a dynamic body's centre of mass; lowest() when there is none.
  double max_height() const;

 private:
  std::unique_ptr<b2World> world_;
  Box2dPileOptions options_;
  std::size_t fixture_count_ = 0;
};

}  // namespace rugosim::bench
