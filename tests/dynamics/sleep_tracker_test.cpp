// The sleep test's two kinds of windows (sleep_tracker.h): a body that rested softly in a
// window must stay within a fifth of a band for four windows; one resting by micro-collisions
// within two bands for two.
#include "engine/dynamics/sleep_tracker.h"

#include <vector>

#include <gtest/gtest.h>

#include "support/test_bodies.h"

namespace rugosim {
namespace {

constexpr double kBand = 1e-3;  // m: λ_a + λ_b of the disk's one contact

struct Outcome {
  double asleep_at = -1.0;  // s, -1: never within the run
};

// A 0.1 m disk on a fixed floor, in contact (band kBand) at every update (every 10 ms for 3 s),
// its pair rested softly or not, moving sideways at `drift` m/s.
Outcome run(bool soft, double drift) {
  const Material stone{1000.0, 0.3, 0.5, 0.0};
  std::vector<RigidBody> bodies = {testing::floor_block(4.0, 0.2, 0.0, stone),
                                   testing::disk(0.1, 16, Vec2(0.0, 0.1), Vec2::Zero(), stone)};
  ContactManifold manifold;
  manifold.body_a = 0;
  manifold.body_b = 1;
  Contact contact;
  contact.lambda_a = contact.lambda_b = 0.5 * kBand;
  manifold.contacts.push_back(contact);
  const std::vector<ContactManifold> manifolds = {manifold};
  const std::vector<BodyPair> near_pairs = {{0, 1}};
  const std::vector<RestedPair> rested = {{0, 1, 0.0, soft}};
  SleepTracker tracker;
  tracker.track(bodies, 0.0);
  Outcome out;
  for (int k = 1; k <= 300 && out.asleep_at < 0.0; ++k) {
    const double time = 0.01 * k;
    BodyState s = bodies[1].state();
    s.position = Vec2(drift * time, 0.1);
    bodies[1].set_state(s);
    tracker.update(bodies, manifolds, near_pairs, rested, time);
    if (tracker.asleep(1)) out.asleep_at = time;
  }
  return out;
}

TEST(SleepTracker, ASoftlyRestedBodyNeedsFourStillWindowsWhereAHardOneNeedsTwo) {
  const Outcome hard = run(false, 0.0);
  const Outcome soft = run(true, 0.0);
  ASSERT_GT(hard.asleep_at, 0.0);
  ASSERT_GT(soft.asleep_at, 0.0);
  // Windows of 0.25 s: two more windows.
  EXPECT_NEAR(soft.asleep_at - hard.asleep_at, 0.5, 1e-9);
}

// Creeping 0.3 band per 0.25 s window: within the hops' allowance (two bands and 1% of the
// radius), beyond the soft allowance (a fifth of a band and 0.05% of the radius, 0.25 mm).
TEST(SleepTracker, ACreepTheHopsExcuseKeepsASoftlyRestedBodyAwake) {
  const double drift = 0.3 * kBand / 0.25;
  EXPECT_GT(run(false, drift).asleep_at, 0.0);
  EXPECT_LT(run(true, drift).asleep_at, 0.0) << "a soft body crept 1.2 bands a second and slept";
  // A fifth of the allowance sleeps.
  EXPECT_GT(run(true, 0.05 * kBand / 0.25).asleep_at, 0.0);
}

}  // namespace
}  // namespace rugosim
