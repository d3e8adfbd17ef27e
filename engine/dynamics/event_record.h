// One impulse applied by the World, as a row of events.csv (INTERFACE.md, "Telemetry files").
#pragma once

#include <cstddef>
#include <string_view>

#include "engine/core/types.h"

namespace rugosim {

// A plain collision (Newton + Coulomb at the real approach speed), or a resting-contact
// micro-collision (paper §4.3: the approach speed perturbed to −√(2gδ), restitution ε_c(δ)).
enum class EventKind { kCollision, kContact };

inline std::string_view to_string(EventKind kind) {
  return kind == EventKind::kCollision ? "collision" : "contact";
}

struct ContactEvent {
  double time = 0.0;  // s
  EventKind kind = EventKind::kCollision;
  std::size_t body_a = 0;  // index of A in the World (add_body order)
  std::size_t body_b = 0;  // index of B
  // Segments and parameters in the input numbering of each body's control points
  // (RigidBody::to_input_param), t in [0, 1).
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  double t_a = 0.0;
  double t_b = 0.0;
  Vec2 point = Vec2::Zero();    // m, world contact point
  Vec2 normal = Vec2::UnitY();  // unit normal of B, from B towards A
  double lambda_a = 0.0;        // m, A's tolerance at t_a
  double lambda_b = 0.0;        // m, B's tolerance at t_b
  double mu = 0.0;              // friction coefficient used
  double vn = 0.0;              // m/s, real relative normal velocity before the impulse
  double vt = 0.0;              // m/s, real relative tangential velocity, t = perp(n)
  double jn = 0.0;              // N·s, normal impulse on A, >= 0
  double jt = 0.0;              // N·s, tangential impulse on A along t
};

}  // namespace rugosim
