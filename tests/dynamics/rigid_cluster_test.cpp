// The rigid-cluster fallback of contact resolution (rigid_cluster.h): momentum kept, kinetic
// energy never added, nothing left approaching.
#include "engine/dynamics/rigid_cluster.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/random.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/contact_resolution.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::disk;
using testing::floor_block;
using testing::make_material;
using testing::scientific;

struct Totals {
  Vec2 linear = Vec2::Zero();  // kg·m/s
  double angular = 0.0;        // kg·m²/s about the origin
  double energy = 0.0;         // J
};

Totals totals(const std::vector<RigidBody>& bodies) {
  Totals t;
  for (const RigidBody& b : bodies) {
    const BodyState& s = b.state();
    t.linear += b.mass() * s.velocity;
    t.angular += b.inertia() * s.angular_velocity + b.mass() * cross(s.position, s.velocity);
    t.energy += b.kinetic_energy();
  }
  return t;
}

std::vector<ContactManifold> detect(const std::vector<RigidBody>& bodies) {
  std::vector<PlacedShape> placed;
  for (const RigidBody& b : bodies)
    placed.push_back({&b.shape(), b.placement(), b.fixed(), false});
  CollisionPipeline pipeline;
  return pipeline.detect(placed);
}

// A row of `count` disks (r = 0.2 m, σ = 2 mm, band 3.6 mm) 1 mm apart, each with a random
// velocity and spin, and optionally a fixed floor 1 mm under them.
std::vector<RigidBody> row(Rng& rng, int count, bool with_floor) {
  std::vector<RigidBody> bodies;
  const Material m = make_material(0.5, 0.5);
  if (with_floor) bodies.push_back(floor_block(4.0, 0.3, 0.0, m, 2e-3));
  for (int i = 0; i < count; ++i) {
    const Vec2 centre(-0.6 + 0.401 * i, 0.201);
    RigidBody b = disk(0.2, 48, centre, Vec2(rng.uniform(-1, 1), rng.uniform(-1, 1)), m, 2e-3);
    BodyState s = b.state();
    s.angular_velocity = rng.uniform(-5, 5);
    b.set_state(s);
    bodies.push_back(b);
  }
  return bodies;
}

ResolutionSettings no_gravity() {
  ResolutionSettings settings;
  settings.gravity = Vec2::Zero();
  return settings;
}

// Free bodies (no fixed one): the cluster takes the rigid motion with the same momentum, so
// linear and angular momentum are kept to rounding and the kinetic energy can only fall.
TEST(RigidCluster, KeepsMomentumAndNeverAddsEnergy) {
  Rng rng(71);
  double worst_momentum = 0.0, worst_angular = 0.0, worst_gain = -1.0;
  int clustered = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<RigidBody> bodies = row(rng, 3, false);
    const std::vector<ContactManifold> manifolds = detect(bodies);
    ASSERT_EQ(manifolds.size(), 2u);  // a chain: 0-1 and 1-2 touch within their bands
    const Totals before = totals(bodies);
    const ClusterCounts counts =
        resolve_rigid_clusters(bodies, manifolds, no_gravity(), 0.0, nullptr);
    const Totals after = totals(bodies);
    if (counts.clusters == 0) continue;  // nothing approached
    ++clustered;
    const double p_scale = before.linear.norm() + 1.0;
    worst_momentum = std::max(worst_momentum, (after.linear - before.linear).norm() / p_scale);
    worst_angular = std::max(
        worst_angular, std::abs(after.angular - before.angular) / (std::abs(before.angular) + 1.0));
    worst_gain = std::max(worst_gain, (after.energy - before.energy) / before.energy);
    EXPECT_FALSE(counts.still_approaching);
    // One rigid motion: every contact's relative velocity is zero up to rounding.
    for (const ContactManifold& m : manifolds) {
      for (const Contact& c : m.contacts) {
        const ContactPlan p = plan_contact(bodies[m.body_a], bodies[m.body_b], c, no_gravity());
        EXPECT_LT(std::abs(p.vn) + std::abs(p.vt), 1e-12);
      }
    }
  }
  RecordProperty("clustered_cases", std::to_string(clustered));
  RecordProperty("worst_momentum_rel", scientific(worst_momentum));
  RecordProperty("worst_angular_rel", scientific(worst_angular));
  RecordProperty("worst_energy_change_rel", scientific(worst_gain));
  EXPECT_GT(clustered, 100);
  EXPECT_LT(worst_momentum, 1e-13);
  EXPECT_LT(worst_angular, 1e-13);
  EXPECT_LE(worst_gain, 1e-14);
}

// With a fixed floor the cluster's contacts with it are resolved with the cluster as one
// body: afterwards none approaches, and the kinetic energy has not grown (no gravity, so no
// micro-collisions: plain collisions with the energy guard).
TEST(RigidCluster, ResolvesContactsWithFixedBodiesAsOneBody) {
  Rng rng(72);
  double worst_gain = -1.0;
  int clustered = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<RigidBody> bodies = row(rng, 3, true);
    const std::vector<ContactManifold> manifolds = detect(bodies);
    const Totals before = totals(bodies);
    const ClusterCounts counts =
        resolve_rigid_clusters(bodies, manifolds, no_gravity(), 0.0, nullptr);
    if (counts.clusters == 0) continue;
    ++clustered;
    EXPECT_EQ(counts.clusters, 1u);
    EXPECT_FALSE(counts.still_approaching);
    worst_gain = std::max(worst_gain, (totals(bodies).energy - before.energy) / before.energy);
    for (const ContactManifold& m : manifolds) {
      for (const Contact& c : m.contacts) {
        EXPECT_FALSE(plan_contact(bodies[m.body_a], bodies[m.body_b], c, no_gravity()).approaching);
      }
    }
  }
  RecordProperty("clustered_cases", std::to_string(clustered));
  RecordProperty("worst_energy_change_rel", scientific(worst_gain));
  EXPECT_GT(clustered, 100);
  EXPECT_LE(worst_gain, 1e-14);
}

// Under mid-step rest (ResolutionSettings::rest_step > 0) a cluster's slow contacts with fixed
// bodies that are no deeper than deep_share of their band are stopped together, inelastically:
// a cluster is a settling pile for an instant, and a micro-collision's hop, √(2·g_n·δ) back out
// of the band, would lift the whole pile as one body (the 50-body pile hopped at 0.22 m/s and
// slept a second later). Deeper contacts keep the hop that lifts them back, as micro-collisions
// alone do for every contact.
TEST(RigidCluster, UnderMidStepRestAClusterStopsOnTheFloorWithoutAHop) {
  const Material m = make_material(0.5, 0.5);
  // Gap to the floor: 2 mm (δ = 0.44 of the 3.6 mm band: shallow) or 1 mm (0.72: deep).
  for (const double gap : {2e-3, 1e-3}) {
    for (const bool mid_step : {false, true}) {
      std::vector<RigidBody> bodies;
      bodies.push_back(floor_block(4.0, 0.3, 0.0, m, 2e-3));
      // Three disks 1 mm apart, closing on each other and settling at 5 cm/s: the cluster's
      // floor contacts are slow (micro-collisions without mid-step rest).
      for (int i = 0; i < 3; ++i) {
        const Vec2 velocity(0.05 * (1 - i), -0.05);
        bodies.push_back(disk(0.2, 48, Vec2(-0.401 + 0.401 * i, 0.2 + gap), velocity, m, 2e-3));
      }
      ResolutionSettings settings;
      settings.rest_step = mid_step ? 1e-3 : 0.0;
      const ClusterCounts counts =
          resolve_rigid_clusters(bodies, detect(bodies), settings, 0.0, nullptr);
      ASSERT_EQ(counts.clusters, 1u);
      EXPECT_FALSE(counts.still_approaching);
      EXPECT_GT(counts.contacts, 0u);  // the floor contacts were slow ones, not collisions
      const bool stopped = mid_step && gap == 2e-3;
      for (std::size_t i = 1; i < bodies.size(); ++i) {
        const double vy = bodies[i].state().velocity.y();
        RecordProperty(std::string(gap == 2e-3 ? "vy_gap_2mm_" : "vy_gap_1mm_") +
                           (mid_step ? "mid_" : "micro_") + std::to_string(i),
                       scientific(vy));
        if (stopped) {
          EXPECT_LE(std::abs(vy), 1e-6) << i;  // neither approaching nor lifted
        } else {
          EXPECT_GT(vy, 0.05) << gap << " " << mid_step << " " << i;  // the hop
        }
      }
    }
  }
}

// Separate clusters stay separate: two pairs far apart become two rigid clusters.
TEST(RigidCluster, SeparateGroupsAreSeparateClusters) {
  const Material m = make_material(0.5, 0.5);
  std::vector<RigidBody> bodies;
  for (const double x : {-3.0, 3.0}) {
    bodies.push_back(disk(0.2, 48, Vec2(x - 0.2005, 0.0), Vec2(1.0, 0.0), m, 2e-3));
    bodies.push_back(disk(0.2, 48, Vec2(x + 0.2005, 0.0), Vec2(-1.0, 0.0), m, 2e-3));
  }
  const ClusterCounts counts =
      resolve_rigid_clusters(bodies, detect(bodies), no_gravity(), 0.0, nullptr);
  EXPECT_EQ(counts.clusters, 2u);
  for (const RigidBody& b : bodies)
    EXPECT_LT(b.state().velocity.norm(), 1e-15);  // head-on equal masses: the pair stops
}

}  // namespace
}  // namespace rugosim
