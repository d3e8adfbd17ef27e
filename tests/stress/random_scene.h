// Seeded random valid scenes for the property-based stress suite (issue 15): every shape kind,
// 4-256 segments, sizes from 1 mm to 100 m, densities 1-20,000, restitution 0-1, friction gains
// 0-10^4, every rugosity form and pattern, every preset, and the arrangements that broke the
// engine before: touching stacks, swarms in closed boxes, squeezes, loose bodies on a floor.
// The same seed always gives the same scene (engine/core/random.h), so a failing seed is a
// reproduction on any machine.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace rugosim::testing {

struct StressScene {
  std::uint64_t seed = 0;
  std::string kind;      // "loose", "stack", "swarm", "squeeze"
  double scale = 1.0;    // m: the typical body size
  nlohmann::json scene;  // a complete scene file (INTERFACE.md); closed containers are the
                         // fixed bodies floor, ceiling, left_wall and right_wall
};

StressScene random_stress_scene(std::uint64_t seed);

}  // namespace rugosim::testing
