// Sleeping (DESIGN.md, "Dynamics"): bodies at rest stop costing time and wake when touched.
//
// Resting bodies under micro-collisions (§4.3) never have zero velocity: they hop inside their
// tolerance band at up to √(2g·band), and rock. So "at rest" is judged on where a body goes,
// not on its velocity. Every half sleep_time of world time (a check), each awake body's pose
// is compared with its pose at the previous check: the window was still when its centre of
// mass moved at most d along each axis and its boundary turned by at most d (angle change ×
// bounding radius), where
//     d = bands × (widest band among its contacts during the window) + tolerance × radius.
// Hops and rocking come back and cancel; a slide or a fall does not. Two still windows in a
// row are needed: a body in free flight can be at the same height at two checks, never at
// three equally spaced ones.
//
// Islands are the bodies linked by near pairs of movable bodies: pairs whose boxes (bands
// included) overlap, as the broad phase finds them. Touching pairs alone would not do:
// bodies hopping in their bands touch and part many times a second, so a pile would split
// into islands that fall asleep one by one and wake each other up. Fixed bodies do not link
// islands (as in Box2D). An island falls asleep when every body in it has been
// still for sleep_time: its velocities are set to zero and its bodies are skipped by free
// flight and by pairs with fixed or sleeping bodies. When an awake movable body touches or
// crosses a sleeping one, the sleeping body's whole island wakes, with fresh anchors.
//
// Bodies that rested softly during a window (soft_rest.h: no hops, they sit within a fifth of
// a band of where they settled) are judged by a stricter test: d = soft_bands × band +
// soft_tolerance × radius, and soft_windows still windows in a row. With the defaults (a
// fifth of a band, 0.05% of the radius, four windows of 0.25 s), a body that sleeps has moved
// at most 0.8 band + 0.2% of its radius over its last second awake: the net creep of issue 14's
// acceptance, bounded by construction. Hard-resting bodies keep the test above, which their
// hops need.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/broad_phase.h"
#include "engine/collision/contact.h"
#include "engine/core/byte_stream.h"
#include "engine/core/disjoint_sets.h"
#include "engine/core/types.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct SleepSettings {
  bool enabled = true;
  // s: how long every body of an island must stay still before it sleeps (Box2D uses 0.5 s):
  // two check windows of half this.
  double time = 0.5;
  // Dimensionless: how many contact bands a resting body may wander. Two: a body hops up to
  // one band, and its neighbours in a pile hop under it too.
  double bands = 2.0;
  // Dimensionless: the part of d proportional to the body's bounding radius. 1% of the radius
  // per 0.25 s window lets a 10 cm body of σ = 0 creep at most 4 mm/s and still sleep (Box2D's
  // fixed tolerance, 5 cm/s, is far looser for bodies of this size).
  double tolerance = 0.01;
  // The stricter test of bodies that rested softly in the window (see above).
  double soft_bands = 0.2;
  double soft_tolerance = 0.0005;
  int soft_windows = 4;
};

struct SleepCounts {
  std::uint64_t islands_slept = 0;  // islands put to sleep
  std::uint64_t islands_woken = 0;  // islands woken by a touch
};

class SleepTracker {
 public:
  explicit SleepTracker(SleepSettings settings = {}) : settings_(settings) {}

  const SleepSettings& settings() const { return settings_; }

  // Grows the per-body records to `bodies` (new bodies start awake, anchored where they are).
  void track(std::span<const RigidBody> bodies, double time);

  // s: world time of the next check (update() judges the bodies at the first call at or after it).
  double next_check() const { return next_check_; }

  bool asleep(std::size_t body) const { return body < asleep_.size() && asleep_[body] != 0; }
  std::size_t asleep_count() const;
  // True when some body that is neither fixed nor asleep exists: otherwise nothing can move.
  bool any_awake_mover(std::span<const RigidBody> bodies) const;

  // Wakes the island of every sleeping body that touches or crosses an awake movable body in
  // `manifolds`; returns how many islands woke.
  std::uint64_t wake_touched(std::span<const RigidBody> bodies,
                             std::span<const ContactManifold> manifolds, double time);

  // Wakes body i's island (e.g. when the caller changes its state); no-op when awake.
  void wake(std::span<const RigidBody> bodies, std::size_t body, double time);

  // After the impulses of an accepted state at `time` (s): notes the widest contact bands and
  // the bodies of pairs that rested softly (`rested`, the step's rest solve), and, when a check
  // is due, judges each awake body's window and puts to sleep every island whose bodies all
  // had enough still windows in a row (two, or soft_windows after a soft window), zeroing their
  // velocities. Returns how many islands fell asleep.
  // `near_pairs` are the broad-phase pairs of the same state (CollisionPipeline::near_pairs).
  std::uint64_t update(std::span<RigidBody> bodies, std::span<const ContactManifold> manifolds,
                       std::span<const BodyPair> near_pairs, std::span<const RestedPair> rested,
                       double time);

  // Checkpoints (World::save_state): every per-body record and the next check, exactly; the
  // scratch of update() is not state. restore throws ByteStreamError when the record does not
  // hold `bodies` bodies.
  void save(ByteWriter& out) const;
  void restore(ByteReader& in, std::size_t bodies);

 private:
  void anchor(const RigidBody& body, std::size_t i, double time);
  void wake_island(std::span<const RigidBody> bodies, std::size_t island, double time);

  SleepSettings settings_;
  // Per body; uint8_t rather than vector<bool> for plain indexing.
  std::vector<std::uint8_t> asleep_;
  std::vector<std::size_t> island_;        // while asleep: the island's smallest body index
  std::vector<Vec2> anchor_position_;      // m
  std::vector<double> anchor_angle_;       // rad
  std::vector<double> anchor_time_;        // s
  std::vector<int> still_windows_;         // still windows in a row, up to now
  double next_check_ = 0.0;                // s: world time of the next check
  std::vector<double> band_seen_;          // m, widest contact band in the current window
  std::vector<std::uint8_t> soft_seen_;    // 1: rested softly in the current window
  std::vector<std::uint8_t> soft_judged_;  // 1: the last window judged was a soft one
  DisjointSets islands_;                   // scratch of update(), reused
  std::vector<std::uint8_t> restless_;     // per island root: scratch of update()
};

}  // namespace rugosim
