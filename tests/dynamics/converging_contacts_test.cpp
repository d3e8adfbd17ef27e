// WorldSettings::converging_contacts: contact rules in which the step enters only as the step,
// checked at three steps against closed forms (issue 17; docs/accuracy/convergence.md).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/world.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::floor_block;
using testing::make_material;
using testing::scientific;

constexpr double kG = 9.81;
constexpr double kRadius = 0.25;
constexpr double kSigma = 0.003;  // the floor's rugosity: a band of millimetres

WorldSettings converging(double max_step) {
  WorldSettings s;
  s.gravity = Vec2(0.0, -kG);
  s.max_step = max_step;
  s.rest_stride = 1;
  s.converging_contacts = true;
  return s;
}

// A disk dropped from rest with its lowest point 0.2 m above a rough floor (ε = 0.5): the first
// impulse is a collision where the gap first equals the band, at t = √(2(0.2 − band)/g),
// whatever the step (to min_step). Off, it lands where the first step's end inside the band
// happens to fall.
class ConvergingAtStep : public ::testing::TestWithParam<double> {};

TEST_P(ConvergingAtStep, AnImpactIsAnsweredWhereThePairArrivesWithinItsBand) {
  for (const bool on : {true, false}) {
    WorldSettings settings = converging(GetParam());
    settings.converging_contacts = on;
    World world(settings);
    world.add_body(floor_block(4.0, 0.4, 0.0, make_material(0.5, 0.5), kSigma), "floor");
    world.add_body(
        disk(kRadius, 64, Vec2(0.0, kRadius + 0.2), Vec2::Zero(), make_material(0.5, 0.5)), "disk");
    world.advance_to(0.3);
    ASSERT_FALSE(world.events().empty());
    const ContactEvent& first = world.events().front();
    const double band = first.lambda_a + first.lambda_b;
    const double expected = std::sqrt(2.0 * (0.2 - band) / kG);
    RecordProperty(on ? "on_time_error" : "off_time_error", scientific(first.time - expected, 3));
    EXPECT_EQ(first.kind, EventKind::kCollision);
    if (on) {
      // The disk's B-spline lies within 2e-7·r of the circle: its gap is exact to well below
      // the 1.9 m/s arrival times 1e-8 s.
      EXPECT_NEAR(first.time, expected, 1e-8) << GetParam();
    } else {
      EXPECT_GE(first.time, expected - 1e-8);
      EXPECT_LE(first.time, expected + GetParam());
    }
    EXPECT_EQ(world.stats().crossings, 0u);
  }
}

// A disk placed at rest at 90% of its band (deeper than the rest depth, a fifth) rises back to
// the rest depth at the rate of a fall through the band, √(2λ/g), not in one step: its height
// at 20 ms is the same at every step to within the step's first-order error, and by 0.5 s it
// rests at the rest depth.
TEST_P(ConvergingAtStep, ADeepContactIsLiftedAtARateOfItsBandNotOfTheStep) {
  const auto height_at = [](double max_step, double t) {
    World world(converging(max_step));
    world.add_body(floor_block(4.0, 0.4, 0.0, make_material(0.0, 0.3), kSigma), "floor");
    // The band, from a contact found at the start (the floor's λ at the disk's foot).
    const std::size_t d = world.add_body(
        disk(kRadius, 64, Vec2(0.0, kRadius + 1e-3), Vec2::Zero(), make_material(0.0, 0.3)),
        "disk");
    world.advance_to(1e-9);
    const double band = world.manifolds().at(0).contacts.at(0).lambda_a +
                        world.manifolds().at(0).contacts.at(0).lambda_b;
    World placed(converging(max_step));
    placed.add_body(floor_block(4.0, 0.4, 0.0, make_material(0.0, 0.3), kSigma), "floor");
    placed.add_body(
        disk(kRadius, 64, Vec2(0.0, kRadius + 0.1 * band), Vec2::Zero(), make_material(0.0, 0.3)),
        "disk");
    placed.advance_to(t);
    return std::make_pair((placed.body(d).state().position.y() - kRadius) / band, band);
  };
  const double h = GetParam();
  const auto [gap_share, band] = height_at(h, 0.02);
  const auto [fine_share, fine_band] = height_at(h / 4, 0.02);
  const double rest_gap_share = 1.0 - MidStepRestSettings{}.rest_depth;
  RecordProperty("gap_share_at_20ms", scientific(gap_share, 4));
  RecordProperty("finer_gap_share_at_20ms", scientific(fine_share, 4));
  // Lifted part of the way (the time constant √(2λ/g) is about 20 ms), and the same way at a
  // quarter of the step, to within the step's share of that time.
  EXPECT_GT(gap_share, 0.2);
  EXPECT_LT(gap_share, rest_gap_share);
  EXPECT_NEAR(gap_share, fine_share, 0.7 * h / std::sqrt(2.0 * band / kG));
  const double rested = height_at(h, 0.5).first;
  EXPECT_NEAR(rested, rest_gap_share, 0.02);
}

INSTANTIATE_TEST_SUITE_P(MaxStep, ConvergingAtStep, ::testing::Values(4e-3, 1e-3, 2.5e-4),
                         [](const ::testing::TestParamInfo<double>& step) {
                           return std::to_string(static_cast<int>(step.param * 1e6)) + "us";
                         });

}  // namespace
}  // namespace rugosim
