// The invariants the stress suite checks on every scene it runs (issue 15), on what the program
// wrote: its trajectory.csv, stats.json and `info --json`.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rugosim::testing {

// One row of trajectory.csv (INTERFACE.md).
struct TrajectoryRow {
  long frame = 0;
  double time = 0.0;
  std::string body;
  double x = 0.0, y = 0.0, angle = 0.0, vx = 0.0, vy = 0.0, omega = 0.0, kinetic_energy = 0.0;
};

// Parses trajectory.csv; nullopt with `error` set when a row is malformed.
std::optional<std::vector<TrajectoryRow>> read_trajectory(const std::string& text,
                                                          std::string* error);

// The inside of a closed container (fixed boxes named floor, ceiling, left_wall and right_wall,
// unrotated), world frame, m; nullopt when the scene has none.
struct InnerBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};
std::optional<InnerBox> closed_container(const nlohmann::json& scene);

// Share of the scene's energy scale (kinetic energy at t = 0 plus the weight of every body
// lifted over the scene's height, the larger of scene_height and the bodies' spread) by which the
// total energy may rise above its start: impulses never add energy, but a resting contact's
// micro-collisions lift a body within its band, and the trajectory samples the energy at frames
// only.
inline constexpr double kEnergyRiseTolerance = 0.01;

// Every invariant of one run, checked; an empty list when all hold.
//   masses: body name -> kg (per unit thickness), from `info --json`
//   gravity: m/s², from the scene
//   scene_height: m, how far the scene reaches up from its lowest body's origin (the height over
//     which the energy scale counts the weights)
std::vector<std::string> check_run(const std::vector<TrajectoryRow>& rows,
                                   const std::map<std::string, double>& masses,
                                   const double gravity[2], double scene_height,
                                   const std::optional<InnerBox>& box, const nlohmann::json& stats);

}  // namespace rugosim::testing
