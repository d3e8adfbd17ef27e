#include "support/pile_scene.h"

#include <cmath>
#include <numbers>

#include "engine/core/random.h"
#include "engine/geometry/shapes.h"

namespace rugosim::testing {
namespace {

constexpr std::size_t kWallSegments = 32;
constexpr double kWallThicknessRadii = 2.0;  // walls and floor are two radii thick

RigidBodyDesc wall(const PileSpec& spec, double width, double height, const Vec2& centre) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(width, height, kWallSegments);
  desc.sigma.assign(kWallSegments, spec.sigma);
  desc.material.density = spec.density;
  desc.material.restitution = spec.restitution;
  desc.material.restitution_max = spec.restitution_max;
  desc.fixed = true;
  desc.position = centre;
  return desc;
}

}  // namespace

std::size_t pile_columns(const PileSpec& spec) {
  const double rows_per_column = 2.0;
  const auto columns = static_cast<std::size_t>(
      std::ceil(std::sqrt(static_cast<double>(spec.bodies) / rows_per_column)));
  return columns < 2 ? 2 : columns;
}

double pile_box_width(const PileSpec& spec) {
  // Half a pitch more than the columns, for the half-pitch shift of odd rows.
  return (static_cast<double>(pile_columns(spec)) + 0.5) * spec.spacing * spec.radius;
}

std::vector<PileBody> pile_scene(const PileSpec& spec) {
  const std::size_t columns = pile_columns(spec);
  const std::size_t rows = (spec.bodies + columns - 1) / columns;
  const double pitch = spec.spacing * spec.radius;
  const double width = pile_box_width(spec);
  const double thickness = kWallThicknessRadii * spec.radius;
  const double wall_height = static_cast<double>(rows + 2) * pitch;

  std::vector<PileBody> scene;
  const Vec2 floor_size(width + 2.0 * thickness, thickness);
  const Vec2 wall_size(thickness, wall_height);
  scene.push_back({wall(spec, floor_size.x(), floor_size.y(), Vec2(0.0, -0.5 * thickness)), "floor",
                   floor_size});
  scene.push_back({wall(spec, wall_size.x(), wall_size.y(),
                        Vec2(-0.5 * (width + thickness), 0.5 * wall_height)),
                   "left_wall", wall_size});
  scene.push_back(
      {wall(spec, wall_size.x(), wall_size.y(), Vec2(0.5 * (width + thickness), 0.5 * wall_height)),
       "right_wall", wall_size});

  Rng rng(spec.seed);
  for (std::size_t i = 0; i < spec.bodies; ++i) {
    const std::size_t row = i / columns;
    const std::size_t column = i % columns;
    RigidBodyDesc desc;
    desc.control_points = blob_control_points(spec.radius, spec.irregularity, spec.segments,
                                              derive_seed(spec.seed, i));
    desc.sigma.assign(spec.segments, spec.sigma);
    desc.material.density = spec.density;
    desc.material.restitution = spec.restitution;
    desc.material.restitution_max = spec.restitution_max;
    // Odd rows shifted by half a pitch so bodies do not stack in exact columns.
    const double shift = row % 2 == 1 ? 0.5 : 0.0;
    desc.position = Vec2(-0.5 * width + (static_cast<double>(column) + 0.5 + shift) * pitch,
                         (static_cast<double>(row) + 0.5) * pitch + 0.1 * spec.radius);
    desc.angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    desc.velocity = Vec2(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.0));
    desc.angular_velocity = rng.uniform(-2.0, 2.0);
    scene.push_back({desc, "body_" + std::to_string(i), Vec2::Zero()});
  }
  return scene;
}

}  // namespace rugosim::testing
