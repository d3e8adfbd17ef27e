// How far resting bodies creep before they sleep (issue 14: "over its last second awake no
// resting body's net displacement exceeds its contact band"). Fed the World after every frame,
// it finds, for each movable body that ends asleep, its last second awake (the frames up to
// the last one before it last fell asleep). A body rested through that second when it touched
// something at every frame of it and always the same bodies (no impact, no partner lost: a
// body that rolls or slides away over new ground does not count as resting, one that creeps
// in place does). Its creep is its net displacement over that second, against the narrowest
// band (λ_a + λ_b) of its contacts at its last awake frame. Shared by the pile test and
// bench_pile.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/world.h"

namespace rugosim::testing {

// Per body of `world`, the narrowest band (λ_a + λ_b, m) among its contacts of touching pairs;
// +inf for a body that touches nothing.
std::vector<double> narrowest_contact_bands(const World& world);

struct RestCreep {
  std::size_t resting = 0;          // bodies that rested through their last awake second
  std::size_t over_band = 0;        // of those, the ones that moved more than their band
  double worst_ratio = 0.0;         // the largest displacement / band among them
  double worst_displacement = 0.0;  // m, that body's displacement
  std::size_t worst_body = 0;
};

class RestCreepTracker {
 public:
  // frames_per_second: how often record() is called (one window is this many frames).
  explicit RestCreepTracker(int frames_per_second) : window_(frames_per_second) {}

  // The World's state after a frame.
  void record(const World& world);

  RestCreep result() const;

 private:
  struct Sample {
    Vec2 position = Vec2::Zero();
    bool asleep = false;
    std::vector<std::size_t> partners;  // sorted
    double narrowest_band = 0.0;        // m, 0 without contacts
  };
  int window_;
  std::vector<std::vector<Sample>> frames_;  // [frame][body]
  std::vector<bool> movable_;
};

}  // namespace rugosim::testing
