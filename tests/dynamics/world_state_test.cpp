// World::save_state and restore_state (world_state.cpp): a World restored from a record saved
// at a frame continues, bit for bit, as the World that saved it (every later frame's full state
// hash and every event), from every 15th frame of a clip; a record that is cut short, altered in
// its counts or saved by another scene is refused and leaves the World as it was.
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/byte_stream.h"
#include "engine/dynamics/state_hash.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"

namespace rugosim {
namespace {

std::string scene_path(const std::string& name) {
  const char* dir = std::getenv("RUGOSIM_SOURCE_DIR");
  return std::string(dir != nullptr ? dir : ".") + "/scenes/" + name + ".json";
}

using Knobs = std::map<std::string, double>;

std::unique_ptr<World> build(const std::string& name, const Knobs& knobs = {}) {
  SceneLoad load = load_scene_file(scene_path(name));
  EXPECT_TRUE(load.ok()) << name;
  for (const auto& [key, value] : knobs)
    load.scene.accuracy.knobs[key] = value;
  SceneWorld built = build_world(load.scene, name);
  EXPECT_TRUE(built.world) << name;
  return std::move(built.world);
}

// What one frame leaves: the full state hash and the events, as text of their exact bits.
struct Frame {
  std::uint64_t hash = 0;
  std::vector<std::string> events;
  friend bool operator==(const Frame&, const Frame&) = default;
};

Frame advance_frame(World& world, std::size_t frame, double fps) {
  world.advance_to(static_cast<double>(frame) / fps);
  Frame f;
  f.hash = full_state_hash(world);
  for (const ContactEvent& e : world.events()) {
    f.events.push_back(std::to_string(e.body_a) + " " + std::to_string(e.body_b) + " " +
                       std::to_string(std::bit_cast<std::uint64_t>(e.time)) + " " +
                       std::to_string(std::bit_cast<std::uint64_t>(e.vn)) + " " +
                       std::to_string(std::bit_cast<std::uint64_t>(e.point.x())));
  }
  world.clear_events();
  return f;
}

void expect_resumes_exactly(const std::string& name, std::size_t last, const Knobs& knobs = {}) {
  const double fps = 30.0;
  std::unique_ptr<World> single = build(name, knobs);
  std::vector<Frame> frames(last + 1);
  std::vector<std::string> records(last + 1);
  for (std::size_t k = 1; k <= last; ++k) {
    frames[k] = advance_frame(*single, k, fps);
    records[k] = single->save_state();
  }
  for (std::size_t k = 15; k < last; k += 15) {
    std::unique_ptr<World> resumed = build(name, knobs);
    resumed->restore_state(records[k]);
    ASSERT_EQ(full_state_hash(*resumed), frames[k].hash) << name << " restored at frame " << k;
    for (std::size_t j = k + 1; j <= last; ++j) {
      ASSERT_EQ(advance_frame(*resumed, j, fps), frames[j])
          << name << " resumed at frame " << k << " differs at frame " << j;
    }
    EXPECT_EQ(resumed->save_state(), records[last]) << name << " from frame " << k;
  }
}

TEST(WorldState, Figure12aResumesExactlyFromEveryFifteenthFrame) {
  expect_resumes_exactly("figure12a", 150);
}

TEST(WorldState, PileResumesExactlyThroughSleepFromEveryFifteenthFrame) {
  // Five seconds: the pile lands, rests and falls asleep, so the sleep records are carried.
  std::unique_ptr<World> probe = build("pile_50");
  probe->advance_to(5.0);
  ASSERT_GT(probe->stats().islands_slept, 0u) << "the pile should be asleep by 5 s";
  expect_resumes_exactly("pile_50", 150);
}

TEST(WorldState, ConvergingContactsResumeExactly) {
  expect_resumes_exactly("figure06_type1_type1", 45, {{"converging_contacts", 1}});
}

// The soft resting solve's impulses carry from step to step: they are state, and a resumed run
// that lost them would differ at its first rest step.
TEST(WorldState, SoftRestResumesExactlyWithItsImpulses) {
  const Knobs soft{{"soft_rest", 8}};
  std::unique_ptr<World> probe = build("pile_50", soft);
  probe->advance_to(2.0);
  ASSERT_FALSE(probe->soft_rest_memory().impulses().empty())
      << "the resting pile should have impulses to remember";
  expect_resumes_exactly("pile_50", 90, soft);
}

TEST(WorldState, RefusesBadRecordsAndKeepsItsState) {
  std::unique_ptr<World> world = build("figure12a");
  world->advance_to(0.5);
  const std::string record = world->save_state();
  std::unique_ptr<World> other = build("figure12a");
  other->advance_to(0.25);
  const std::uint64_t before = full_state_hash(*other);
  for (std::size_t cut : {std::size_t{0}, std::size_t{7}, record.size() / 2, record.size() - 1}) {
    EXPECT_THROW(other->restore_state(record.substr(0, cut)), ByteStreamError) << cut;
  }
  EXPECT_THROW(other->restore_state(record + "x"), ByteStreamError);
  std::string huge_count = record;
  huge_count[8 + 7] = '\x7f';  // the number of bodies, made enormous
  EXPECT_THROW(other->restore_state(huge_count), ByteStreamError);
  std::unique_ptr<World> pile = build("pile_50");
  EXPECT_THROW(pile->restore_state(record), ByteStreamError);
  EXPECT_EQ(full_state_hash(*other), before);
  other->restore_state(record);
  EXPECT_EQ(full_state_hash(*other), full_state_hash(*world));
}

}  // namespace
}  // namespace rugosim
