// The validation scenes (scenes/validation_*.json) run in Box2D 2.4.1 (Debian libbox2d-dev),
// the peer engine, so that the accuracy study can measure both engines with the same closed
// forms (accuracy_metrics.h) and compare errors at equal wall time. The Box2D world is built
// from the scene file itself, through the rugosim World built from it (shapes, μ from σ,
// restitution, density, gravity, placements and velocities), never from copied numbers.
//
// What the translation does, and what it cannot do:
// - Box2D is single precision (float): positions, velocities and masses carry ~1e-7 relative
//   rounding, and its tolerances are absolute lengths (a 5 mm linear slop, a 1 cm polygon skin),
//   hence length_scale below.
// - Disks ("circle" shapes) become b2CircleShape, or with circles = false a regular 32-gon with
//   its vertices on the circle (a fan of 8 convex pieces, Box2D allowing 8 vertices a polygon),
//   whose area is (32/2π)·sin(2π/32) = 99.36% of the disk's. Sharp boxes become boxes. Other
//   shapes (blobs, ellipses, free outlines, rounded polygons) throw std::invalid_argument.
// - μ of a fixture is the rugosim body's friction_coefficient (paper §4.2) on the boundary it
//   stands for. Box2D mixes sqrt(μa·μb); a contact listener sets max(μa, μb) in PreSolve, as
//   rugosim's contact_friction does. Restitution is the material's ε, and Box2D's own mixing,
//   max(εa, εb), is already rugosim's, so it is left alone.
// - A fixed box whose μ varies along its top face (the rough patch floor) becomes full-height
//   box fixtures side by side, one under each run of equal μ along the top face, each with its
//   μ. μ varies per fixture only: the continuous blend of λ(t) between segments becomes a step,
//   and the other faces take the μ of the slab they bound.
// - Box2D's restitution threshold (b2FixtureDef::restitutionThreshold, 1 m/s by default, mixed
//   as the smaller of the two): slower impacts do not bounce at all. The bouncing disk's third
//   impact comes at 0.96 m/s, so the default would end it there; restitution_threshold below
//   defaults to 1 mm/s.
// - Box2D's polygons (boxes, the floors) carry a skin of b2_polygonRadius = 1 cm in Box2D
//   units: a disk rests and bounces 1 cm / length_scale above a box's face. The bouncing disk's
//   apex ratios, measured from the face, feel it at each lower apex: at 240 Hz their error was
//   0.61 at length_scale 1, 0.26 at 2 (suggested_length_scale) and 0.037 at 10.
// - Box2D's defaults are kept otherwise: bodies at rest fall asleep, continuous collision
//   against static bodies is on.
// - Rugosity tolerance bands, micro-collisions and ε_max have no Box2D counterpart.
//
// Box2D is included by the .cpp files only, so code including this header needs neither its
// include path nor its headers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accuracy_metrics.h"
#include "engine/core/types.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"

namespace rugosim::bench {

struct Box2dSceneOptions {
  double hz = 60.0;             // Box2D steps per second: it steps at a fixed 1/hz
  int velocity_iterations = 8;  // Box2D's recommended values
  int position_iterations = 3;
  bool circles = true;  // disks as b2CircleShape, else as an inscribed regular 32-gon
  // Box2D lengths per metre, > 0. Box2D's tolerances are absolute (tuned for bodies of 0.1 to
  // 10 m). A scale L builds the same scene in units of 1/L m: lengths, velocities and gravity
  // ×L, the restitution threshold ×L, density /L² so that masses stay in kg. Every answer
  // below is in SI units whatever L. suggested_length_scale() makes the bodies ~1 unit.
  double length_scale = 1.0;
  // m/s (SI, scaled with lengths): impacts slower than this do not bounce in Box2D. Its
  // default, 1 m/s, stops the bouncing disk after two bounces; 1 mm/s lets every bounce of the
  // validation scenes happen. Scenes with ε = 0 do not depend on it.
  double restitution_threshold = 1e-3;
};

// Box2D lengths per metre that make the largest movable body ~1 Box2D unit across (1 / its
// bounding diameter), the size Box2D's absolute tolerances are tuned for.
double suggested_length_scale(const World& world);

// Runs `scene` (loaded from `file`) in Box2D for its duration, `repeats` times, and keeps the
// fastest run's wall time (the runs are identical, Box2D being deterministic). The Run's world
// is the rugosim World built from the same scene, never stepped, so closed_form_error reads μ,
// gravity and restitution from it; its frames hold Box2D's states at every frame time k/fps,
// with rugosim's BodyState conventions (centre of mass, angle counter-clockwise, velocity of
// the centre of mass); stats stay empty. Box2D steps at a fixed 1/hz; a frame time between two
// steps gets the state after the last step not beyond it (Box2D is not sub-stepped, since a
// shorter step would change its warm starting and position correction). wall_s times the
// stepping and the reading of states, as run_scene times rugosim's. Throws
// std::invalid_argument for bad options or an unsupported body (naming it), and
// std::runtime_error when the scene does not build.
study::Run run_box2d_scene(const Scene& scene, const std::string& file,
                           const Box2dSceneOptions& options, int repeats = 1);

// Mass properties of a movable body as Box2D computed them from its fixtures, in SI units.
struct Box2dMass {
  std::size_t body = 0;  // index in the scene
  std::string name;
  double mass = 0.0;     // kg
  double inertia = 0.0;  // kg·m², about the centre of mass
};
std::vector<Box2dMass> box2d_masses(const Scene& scene, const std::string& file,
                                    const Box2dSceneOptions& options);

// One Box2D fixture, in SI units and world coordinates at t = 0: what the translation made of
// a body's boundary, for checking.
struct Box2dFixture {
  std::size_t body = 0;  // index in the scene
  std::string kind;      // "circle" or "polygon"
  double friction = 0.0;
  double restitution = 0.0;
  std::vector<Vec2> vertices;  // m: a polygon's vertices, or a circle's centre
  double radius = 0.0;         // m, a circle's
};
std::vector<Box2dFixture> box2d_fixtures(const Scene& scene, const std::string& file,
                                         const Box2dSceneOptions& options);

}  // namespace rugosim::bench
