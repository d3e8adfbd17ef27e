// What the collision layer reports about two placed bodies (paper §3.2).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/core/types.h"

namespace rugosim {

// State of two boundary pieces (§3.2): they cross, they are within their combined tolerance
// band (a tolerated contact), or they are apart.
enum class PairState { kSeparated, kContact, kIntersecting };

// One tolerated contact between segment `segment_a` of body A and `segment_b` of body B.
struct Contact {
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  double t_a = 0.0;             // parameter of A's nearest point, in [0, 1]
  double t_b = 0.0;             // parameter of B's nearest point, in [0, 1]
  double lambda_a = 0.0;        // m, A's interpolated tolerance λ_a(t_a)
  double lambda_b = 0.0;        // m, B's interpolated tolerance λ_b(t_b)
  Vec2 point_a = Vec2::Zero();  // m, world: nearest point on A
  Vec2 point_b = Vec2::Zero();  // m, world: nearest point on B
  Vec2 point = Vec2::Zero();    // m, world: p = b(t_b) + d/2, the midpoint (DESIGN.md erratum)
  Vec2 normal = Vec2::UnitY();  // unit normal of B at p, pointing from B towards A
  double distance = 0.0;        // m, ‖d‖ = ‖a(t_a) − b(t_b)‖, at most λ_a + λ_b
};

// A place where the two boundaries cross: the step that led here must be backed off.
struct Intersection {
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  double t_a = 0.0;
  double t_b = 0.0;
  Vec2 point = Vec2::Zero();  // m, world
};

// Everything found between two bodies A and B: crossings first (any crossing makes the pair
// intersecting), otherwise the merged tolerated contacts.
struct ContactManifold {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  std::vector<Intersection> intersections;
  std::vector<Contact> contacts;

  PairState state() const {
    if (!intersections.empty()) return PairState::kIntersecting;
    return contacts.empty() ? PairState::kSeparated : PairState::kContact;
  }
};

}  // namespace rugosim
