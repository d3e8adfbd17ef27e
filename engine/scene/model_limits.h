// What rugosim cannot model, refused with the body's JSON path before a World runs (exit 2):
//   - a body less than 1 µm or more than 10,000 km across: its tolerances are relative (the
//     narrow phase resolves 1e-12 of a segment, the smallest band is 1e-6 of a body), and
//     outside that range they meet the limits of double precision or of the tests behind them;
//   - a body farther from the origin than 10⁶ times its size: its coordinates could no longer
//     resolve its smallest band (rounding is 1e-16 of their magnitude);
//   - a rugosity band (the largest λ of the body) wider than half the body's thickness: a
//     contact inside it would reach through the body;
//   - a speed (|v| + |ω|·radius) so high that in one time-of-impact tolerance a body moves a
//     quarter of the thinnest body's thickness: no step could be short enough to see it hit.
#pragma once

#include <string>
#include <vector>

#include "engine/dynamics/world.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

namespace rugosim {

inline constexpr double kMinBodySize = 1e-6;         // m
inline constexpr double kMaxBodySize = 1e7;          // m
inline constexpr double kMaxDistanceOverSize = 1e6;  // from the origin, in body sizes

std::vector<SceneError> check_model_limits(const World& world, const Scene& scene,
                                           const std::string& file);

}  // namespace rugosim
