// The soft resting solve (engine/dynamics/soft_rest.h; the `soft_rest` accuracy knob): its
// impulse memory (one impulse per key, the later kept, saved and restored exactly, bad records
// refused), and what it is for: a dropped body and a pile come to rest within their bands and
// sleep, with no crossing, deterministically and whatever the thread count.
#include "engine/dynamics/soft_rest.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/byte_stream.h"
#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/world.h"
#include "engine/geometry/shapes.h"
#include "support/pile_scene.h"
#include "support/rest_creep.h"
#include "support/test_bodies.h"
#include "support/test_output.h"

namespace rugosim {
namespace {

using testing::scientific;

// Every island rests softly (soft_rest_island 1), lone bodies too, so that one body shows it.
WorldSettings soft_settings(int substeps = 8, int threads = 1) {
  Accuracy accuracy;
  accuracy.soft_rest = substeps;
  accuracy.soft_rest_island = 1;
  WorldSettings base;
  base.threads = threads;
  return with_accuracy(base, accuracy);
}

TEST(SoftRestMemory, KeepsOneImpulsePerKeyTheLaterOneSortedAndFindsIt) {
  SoftRestMemory memory;
  memory.replace(1e-3, {{2, 5, 1, 0, 3.0, 0.5}, {0, 1, 7, 2, 1.0, -0.25}, {2, 5, 1, 0, 4.0, 0.1}});
  ASSERT_EQ(memory.impulses().size(), 2u);
  EXPECT_EQ(memory.substep(), 1e-3);
  EXPECT_EQ(memory.impulses()[0].body_a, 0u);
  const SoftRestImpulse* later = memory.find(2, 5, 1, 0);
  ASSERT_NE(later, nullptr);
  EXPECT_EQ(later->normal, 4.0);
  EXPECT_EQ(later->tangent, 0.1);
  EXPECT_EQ(memory.find(2, 5, 0, 1), nullptr);
  EXPECT_EQ(memory.find(0, 1, 7, 3), nullptr);
  memory.replace(2e-3, {});
  EXPECT_EQ(memory.substep(), 0.0) << "an empty memory carries nothing";
}

TEST(SoftRestMemory, SavesAndRestoresExactlyAndRefusesIndicesPastTheBodies) {
  const Material stone{1000.0, 0.3, 0.5, 0.0};
  std::vector<RigidBody> bodies = {testing::floor_block(4.0, 0.2, 0.0, stone),
                                   testing::disk(0.1, 16, Vec2(0.0, 0.1), Vec2::Zero(), stone)};
  SoftRestMemory memory;
  memory.replace(0.1 / 3.0, {{0, 1, 31, 15, 0.1 / 7.0, -1e-300}});
  ByteWriter out;
  memory.save(out);
  SoftRestMemory restored;
  ByteReader in(out.bytes());
  restored.restore(in, bodies);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(restored, memory);

  for (const SoftRestImpulse bad : {SoftRestImpulse{0, 2, 0, 0, 1.0, 0.0},      // body 2 of 2
                                    SoftRestImpulse{0, 1, 32, 0, 1.0, 0.0},     // floor has 32
                                    SoftRestImpulse{0, 1, 0, 16, 1.0, 0.0}}) {  // disk has 16
    SoftRestMemory wrong;
    wrong.replace(1e-3, {bad});
    ByteWriter w;
    wrong.save(w);
    ByteReader r(w.bytes());
    SoftRestMemory target = memory;
    EXPECT_THROW(target.restore(r, bodies), ByteStreamError);
    EXPECT_EQ(target, memory) << "a refused record leaves the memory as it was";
  }
}

// Islands are the moving bodies linked by pairs in contact; a fixed or sleeping body (not
// moving) links nothing, and a pair that only crosses or is near links nothing either.
TEST(SoftRestMovers, TakeTheMovingBodiesOfIslandsOfAtLeastTheGivenSize) {
  const auto pair = [](std::size_t a, std::size_t b, PairState state) {
    ContactManifold m;
    m.body_a = a;
    m.body_b = b;
    if (state == PairState::kContact) m.contacts.emplace_back();
    if (state == PairState::kIntersecting) m.intersections.emplace_back();
    return m;
  };
  // 0 is fixed and 7 asleep (neither moves). 1–2–3: a chain in contact, on the floor. 4 lies
  // on the floor alone and 5 crosses it (no link); 6 touches the floor and 7, and is only near
  // 3: islands of one.
  const std::vector<std::uint8_t> moves = {0, 1, 1, 1, 1, 1, 1, 0};
  const std::vector<ContactManifold> manifolds = {
      pair(0, 1, PairState::kContact), pair(0, 4, PairState::kContact),
      pair(0, 6, PairState::kContact), pair(1, 2, PairState::kContact),
      pair(2, 3, PairState::kContact), pair(4, 5, PairState::kIntersecting),
      pair(6, 7, PairState::kContact), pair(3, 6, PairState::kSeparated)};
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 1), moves);
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 2),
            (std::vector<std::uint8_t>{0, 1, 1, 1, 0, 0, 0, 0}));
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 3),
            (std::vector<std::uint8_t>{0, 1, 1, 1, 0, 0, 0, 0}));
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 4), std::vector<std::uint8_t>(8, 0));
}

// An island with a contact narrower than min_band (σ = 0 bodies: their band is the minimum
// one) keeps the mid-step solve whole, even where its other contacts are wide; a fixed body's
// contact counts for the island it touches.
TEST(SoftRestMovers, LeaveIslandsWithANarrowContactToTheMidStepSolve) {
  const auto pair = [](std::size_t a, std::size_t b, double band) {
    ContactManifold m;
    m.body_a = a;
    m.body_b = b;
    Contact c;
    c.lambda_a = 0.5 * band;
    c.lambda_b = 0.5 * band;
    m.contacts.push_back(c);
    return m;
  };
  // 0 is fixed. Island 1–2 (wide), island 3–4 (3–4 narrow), island 5–6 (5 on the floor narrow).
  const std::vector<std::uint8_t> moves = {0, 1, 1, 1, 1, 1, 1};
  const std::vector<ContactManifold> manifolds = {pair(0, 1, 1e-3), pair(0, 3, 1e-3),
                                                  pair(0, 5, 1e-5), pair(1, 2, 1e-3),
                                                  pair(3, 4, 1e-5), pair(5, 6, 1e-3)};
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 2, 1e-4),
            (std::vector<std::uint8_t>{0, 1, 1, 0, 0, 0, 0}));
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 1, 1e-6), moves);
  EXPECT_EQ(soft_rest_movers(moves, manifolds, 1, 1e-2), std::vector<std::uint8_t>(7, 0));
  // 60 Hz under 9.81 m/s²: ten times the spring's sag g/ω² (0.069 mm), 0.69 mm.
  EXPECT_NEAR(soft_rest_min_band(Vec2(0.0, -9.81), 60.0), 6.9e-4, 1e-6);
}

// soft_rest replaces the mid-step solve: with mid_step_rest 0 (micro-collisions alone) neither
// runs, so turning the mid-step solve off keeps its meaning whatever soft_rest says. A resting
// disk then hops on micro-collisions and nothing is softly rested.
TEST(SoftRest, ReplacesTheMidStepRestAndIsOffWithIt) {
  Accuracy accuracy;
  EXPECT_EQ(accuracy.soft_rest, 8) << "normal rests softly";
  EXPECT_EQ(accuracy_preset("draft")->soft_rest, 0) << "draft's 2 ms steps keep the mid-step solve";
  EXPECT_EQ(accuracy_preset("precise")->soft_rest, 0) << "precise keeps the exact solve";
  const WorldSettings settings = with_accuracy(WorldSettings{}, accuracy);
  EXPECT_EQ(settings.soft_rest_substeps, 8);
  EXPECT_EQ(settings.soft_rest_island, 2) << "lone bodies keep the mid-step solve by default";
  accuracy.mid_step_rest = 0;
  accuracy.soft_rest_island = 1;  // the lone disk would be softly rested, were the solve on
  World world(with_accuracy(WorldSettings{}, accuracy));
  world.add_body(testing::floor_block(3.0, 0.3, 0.0, testing::make_material(0.3, 0.5), 1e-3));
  world.add_body(testing::disk(0.2, 48, Vec2(0.0, 0.201), Vec2::Zero(),
                               testing::make_material(0.3, 0.5), 1e-3));
  world.advance_to(0.5);
  EXPECT_EQ(world.stats().rest_contacts, 0u);
  EXPECT_GT(world.stats().contacts, 0u) << "resting by micro-collisions";
}

// A rough disk dropped on a rough floor lands, rests within its band, and sleeps; asleep it
// stays where it rested, the floor never crossed.
TEST(SoftRest, ADroppedDiskRestsWithinItsBandAndSleeps) {
  const Material stone{1000.0, 0.3, 0.5, 0.0};
  World world(soft_settings());
  world.add_body(testing::floor_block(4.0, 0.2, 0.0, stone, 0.002), "floor");
  world.add_body(testing::disk(0.1, 16, Vec2(0.0, 0.3), Vec2::Zero(), stone, 0.002), "disk");
  double asleep_at = -1.0;
  for (int frame = 1; frame <= 150 && asleep_at < 0.0; ++frame) {
    world.advance_to(frame / 30.0);
    if (world.asleep(1)) asleep_at = world.time();
  }
  RecordProperty("asleep_at_s", scientific(asleep_at, 3));
  RecordProperty("steps", std::to_string(world.stats().steps));
  ASSERT_GT(asleep_at, 0.0) << "the disk did not sleep within 5 s";
  EXPECT_EQ(world.stats().crossings, 0u);
  // Rests within its band (λ_a + λ_b = 3.6 mm with q = 0.9): the centre between the radius
  // above the floor and the radius plus the band.
  const double band = 0.9 * (0.002 + 0.002);
  const double height = world.body(1).state().position.y();
  EXPECT_GT(height, 0.1 - 1e-9);
  EXPECT_LT(height, 0.1 + band);
  EXPECT_EQ(testing::pair_state(world, 0, 1), PairState::kContact);
}

// A block alone on an incline below its friction angle (tanθ = 0.3, μ = 0.45): in an island of
// one, below soft_rest_island 2, it keeps the mid-step solve's exact rest (no creep, to the
// 1e-8 m of the mid-step tests), where the soft solve's springs let it creep. Measured
// (release) over [0.3, 1.3] s: 4.9e-9 m with island 2 (it still settles into its band), 5.4e-7
// m with island 1 (validation_incline_below: 8.6e-10 and 1.5e-5 m over 3 s).
TEST(SoftRest, AnIslandBelowTheSoftSizeKeepsTheExactRestOfTheMidStepSolve) {
  const auto creep = [](int island) {
    Accuracy accuracy;
    accuracy.soft_rest = 8;
    accuracy.soft_rest_island = island;
    WorldSettings base;
    base.gravity = 9.81 * Vec2(std::sin(std::atan(0.3)), -std::cos(std::atan(0.3)));
    World world(with_accuracy(base, accuracy));
    const Material stone{1000.0, 0.0, 0.3, 0.0};
    world.add_body(testing::floor_block(8.0, 0.4, 0.0, stone, 0.005), "incline");
    RigidBodyDesc block;
    block.control_points = box_control_points(0.4, 0.2, 16);
    block.material = stone;
    block.position = Vec2(-2.0, 0.1 + 0.5 * 0.9 * 0.005);
    world.add_body(RigidBody(block), "block");
    world.advance_to(0.3);
    const double x0 = world.body(1).state().position.x();
    world.advance_to(1.3);
    EXPECT_EQ(world.stats().crossings, 0u);
    return world.body(1).state().position.x() - x0;
  };
  const double hard = creep(2);
  const double soft = creep(1);
  RecordProperty("creep_island_2_m", scientific(hard, 3));
  RecordProperty("creep_island_1_m", scientific(soft, 3));
  EXPECT_LT(std::abs(hard), 1e-8);
  EXPECT_LT(std::abs(soft), 1e-3) << "the soft solve still holds the block, if not exactly";
}

// The 50-body pile of bench_pile rests and sleeps under the soft solve, with no crossing, and
// no resting body moves more than its band over its last second awake. Measured (release):
// asleep at 2.5 s, worst creep 0.01 band.
TEST(SoftRest, APileSleepsWithoutCreepOrCrossing) {
  testing::PileSpec spec;
  spec.bodies = 50;
  World world(soft_settings());
  for (const testing::PileBody& b : testing::pile_scene(spec))
    world.add_body(RigidBody(b.desc), b.name);
  testing::RestCreepTracker tracker(30);
  double all_asleep_at = -1.0;
  for (int frame = 1; frame <= 150; ++frame) {
    world.advance_to(frame / 30.0);
    tracker.record(world);
    bool all = true;
    for (std::size_t i = 3; i < world.body_count(); ++i)
      all = all && world.asleep(i);
    if (all && all_asleep_at < 0.0) all_asleep_at = world.time();
  }
  const testing::RestCreep creep = tracker.result();
  RecordProperty("all_asleep_at_s", scientific(all_asleep_at, 3));
  RecordProperty("worst_displacement_in_bands", scientific(creep.worst_ratio, 3));
  RecordProperty("steps", std::to_string(world.stats().steps));
  EXPECT_GT(all_asleep_at, 0.0) << "the pile did not sleep within 5 s";
  EXPECT_GE(creep.resting, 10u);
  EXPECT_EQ(creep.over_band, 0u) << world.name(creep.worst_body) << " moved " << creep.worst_ratio
                                 << " bands";
  EXPECT_EQ(world.stats().crossings, 0u);
  for (const ContactManifold& m : testing::detect_all(world))
    EXPECT_NE(m.state(), PairState::kIntersecting) << m.body_a << " x " << m.body_b;
}

// A column of 24 rough disks on a rough floor: the lowest contacts carry the weight of twenty
// and more, which one sweep per substep carries down slowly. With every spring at 60 Hz two of
// its rest steps crossed and had their rest withdrawn (measured, release); with the loaded
// contacts' springs stiffened (rest_softly, §8.20) none does. Every contact keeps at least half
// the room between its rest depth and the curves touching (measured: 2.77 mm of distance,
// 2.88 mm at the rest depth).
TEST(SoftRest, ALoadedColumnRestsWithoutCrossing) {
  const Material stone{1000.0, 0.3, 0.5, 0.0};
  const double radius = 0.05;
  const double sigma = 0.002;
  const double band = 0.9 * (sigma + sigma);  // λ_a + λ_b of two such surfaces
  World world(soft_settings());
  world.add_body(testing::floor_block(1.0, 0.2, 0.0, stone, sigma), "floor");
  const int disks = 24;
  for (int i = 0; i < disks; ++i) {
    const double y = radius + 0.5 * band + i * (2.0 * radius + 0.5 * band);
    world.add_body(testing::disk(radius, 16, Vec2(0.0, y), Vec2::Zero(), stone, sigma));
  }
  world.advance_to(1.5);
  EXPECT_EQ(world.stats().crossings, 0u);
  EXPECT_EQ(world.stats().rest_withdrawn, 0u);
  const double room = (1.0 - WorldSettings{}.rest_depth) * band;
  double least = band;
  for (const ContactManifold& m : testing::detect_all(world)) {
    ASSERT_NE(m.state(), PairState::kIntersecting) << m.body_a << " x " << m.body_b;
    for (const Contact& c : m.contacts)
      least = std::min(least, c.distance);
  }
  RecordProperty("least_distance_m", scientific(least, 3));
  EXPECT_GT(least, 0.5 * room) << "a loaded contact sagged past half its room";
}

// Threads never change a result, with the soft solve too: states and statistics bit for bit.
TEST(SoftRest, ThreadsChangeNothing) {
  testing::PileSpec spec;
  spec.bodies = 30;
  auto run = [&](int threads) {
    World world(soft_settings(8, threads));
    for (const testing::PileBody& b : testing::pile_scene(spec))
      world.add_body(RigidBody(b.desc), b.name);
    world.advance_to(1.5);
    return world.save_state();
  };
  const std::string one = run(1);
  for (const int threads : {2, 3, 8})
    EXPECT_EQ(run(threads), one) << threads << " threads";
}

}  // namespace
}  // namespace rugosim
