// Mid-step rest on a stack it cannot solve in its sweeps: a heavy crate on light ones, placed
// touching, with bands of a few micrometres (σ = 0). Gauss-Seidel carries the top crate's weight
// down a few hundredths per sweep, so after 64 sweeps a light crate's contacts still close faster
// than their gaps allow; before World::step withdrew the impulses of a crossing island, such
// stacks (stress seeds 1, 5, 13, 19, 25 with the knob) accepted a crossing at nearly every step.
#include <string>

#include <gtest/gtest.h>

#include "engine/dynamics/world.h"
#include "engine/geometry/shapes.h"
#include "support/test_bodies.h"

namespace rugosim {
namespace {

RigidBody crate(double width, double height, double bottom, double density) {
  RigidBodyDesc desc;
  desc.control_points = box_control_points(width, height, 16);
  desc.material.density = density;
  desc.material.restitution = 0.2;
  desc.material.restitution_max = 0.6;
  desc.position = Vec2(0.0, bottom + 0.5 * height);
  return RigidBody(desc);
}

class MidStepRestStack : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(MaxStep, MidStepRestStack, ::testing::Values(4e-3, 1e-3),
                         [](const ::testing::TestParamInfo<double>& step) {
                           return std::to_string(static_cast<int>(step.param * 1e6)) + "us";
                         });

TEST_P(MidStepRestStack, HeavyCrateOnLightOnesNeverCrosses) {
  WorldSettings settings;
  settings.max_step = GetParam();
  settings.mid_step_rest = true;
  settings.record_events = false;
  World world(settings);
  world.add_body(testing::floor_block(36.0, 1.8, 0.0, Material{}), "floor");
  // Densities of stress seed 25: 45 and 21 kg/m² under 10,825 (a mass ratio of about 600).
  world.add_body(crate(1.09, 1.50, 0.0, 45.0), "light_0");
  world.add_body(crate(1.08, 1.66, 1.50, 21.0), "light_1");
  world.add_body(crate(2.78, 0.78, 3.16, 10825.0), "heavy");
  world.advance_to(0.5);

  const StepStats& stats = world.stats();
  EXPECT_EQ(stats.crossings, 0u);
  EXPECT_EQ(stats.crossing_fallbacks, 0u);
  // The case this guards: the solve ran out of sweeps and a crossing island went on without it.
  EXPECT_GT(stats.rest_unconverged, 0u);
  EXPECT_GT(stats.rest_withdrawn, 0u);
  for (std::size_t a = 0; a < world.body_count(); ++a) {
    for (std::size_t b = a + 1; b < world.body_count(); ++b) {
      EXPECT_NE(testing::pair_state(world, a, b), PairState::kIntersecting) << a << ", " << b;
    }
  }
  // Held by the contact model, not by the back-off's last resorts (stopping or holding bodies).
  EXPECT_EQ(stats.stalled_steps, 0u);
  EXPECT_EQ(stats.min_step_fallbacks, 0u);
  RecordProperty("rest_withdrawn", std::to_string(stats.rest_withdrawn));
  RecordProperty("rest_unconverged", std::to_string(stats.rest_unconverged));
  // The stack stands: the heavy crate's centre, 3.55 m up at the start, sinks by no more than
  // the crates' bands (a few micrometres each) and rounding.
  EXPECT_NEAR(world.body(3).state().position.y(), 3.16 + 0.39, 1e-4);
}

}  // namespace
}  // namespace rugosim
