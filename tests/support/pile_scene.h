// The pile scene shared by the dynamics tests and the benchmarks (as Box2D shares its
// benchmark scenes): irregular bodies dropped in rows into an open box and left to settle.
// Everything is seeded, so a given PileSpec always builds the same bodies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim::testing {

struct PileSpec {
  std::size_t bodies = 20;
  std::size_t segments = 24;  // B-spline segments per falling body
  double radius = 0.1;        // m, mean radius of a body
  double irregularity = 0.4;  // blob irregularity (shapes.h), concave outlines included
  double spacing = 3.0;       // grid pitch in radii: > 2(1 + irregularity), so bodies start apart
  double sigma = 0.003;       // m, rugosity of every segment (falling bodies and the box)
  double restitution = 0.3;   // ε
  double restitution_max = 0.5;  // ε_max
  double density = 1000.0;       // kg/m²
  std::uint64_t seed = 1;
};

struct PileBody {
  RigidBodyDesc desc;
  std::string name;
  Vec2 box_size = Vec2::Zero();  // m: a wall's width and height (zero for a falling body)
};

// Columns of the grid: about twice as many rows as columns, like a hopper.
std::size_t pile_columns(const PileSpec& spec);

// m: inner width of the box (its floor's top face is y = 0, its walls at x = ±width/2).
double pile_box_width(const PileSpec& spec);

// The fixed box (floor, left wall, right wall: sharp boxes, σ as the bodies) and then the
// falling bodies, row by row from the bottom, with seeded outlines, angles and small
// velocities. The first three are fixed.
std::vector<PileBody> pile_scene(const PileSpec& spec);

}  // namespace rugosim::testing
