#include "engine/dynamics/sleep_tracker.h"

#include <algorithm>
#include <cmath>

namespace rugosim {
namespace {

bool touching(const ContactManifold& m) {
  return m.state() != PairState::kSeparated;
}

}  // namespace

void SleepTracker::track(std::span<const RigidBody> bodies, double time) {
  for (std::size_t i = asleep_.size(); i < bodies.size(); ++i) {
    asleep_.push_back(0);
    island_.push_back(i);
    anchor_position_.push_back(bodies[i].state().position);
    anchor_angle_.push_back(bodies[i].state().angle);
    anchor_time_.push_back(time);
    still_windows_.push_back(0);
    band_seen_.push_back(0.0);
    soft_seen_.push_back(0);
    soft_judged_.push_back(0);
  }
}

std::size_t SleepTracker::asleep_count() const {
  return static_cast<std::size_t>(std::count(asleep_.begin(), asleep_.end(), 1));
}

bool SleepTracker::any_awake_mover(std::span<const RigidBody> bodies) const {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!bodies[i].fixed() && !asleep(i)) return true;
  }
  return false;
}

void SleepTracker::anchor(const RigidBody& body, std::size_t i, double time) {
  anchor_position_[i] = body.state().position;
  anchor_angle_[i] = body.state().angle;
  anchor_time_[i] = time;
  band_seen_[i] = 0.0;
  soft_seen_[i] = 0;
}

void SleepTracker::wake_island(std::span<const RigidBody> bodies, std::size_t island, double time) {
  for (std::size_t i = 0; i < asleep_.size(); ++i) {
    if (asleep_[i] == 0 || island_[i] != island) continue;
    asleep_[i] = 0;
    island_[i] = i;
    still_windows_[i] = 0;
    anchor(bodies[i], i, time);
  }
}

void SleepTracker::wake(std::span<const RigidBody> bodies, std::size_t body, double time) {
  if (asleep(body)) wake_island(bodies, island_[body], time);
}

std::uint64_t SleepTracker::wake_touched(std::span<const RigidBody> bodies,
                                         std::span<const ContactManifold> manifolds, double time) {
  std::uint64_t woken = 0;
  for (const ContactManifold& m : manifolds) {
    if (!touching(m)) continue;
    const std::size_t a = m.body_a;
    const std::size_t b = m.body_b;
    const bool a_awake_mover = !bodies[a].fixed() && !asleep(a);
    const bool b_awake_mover = !bodies[b].fixed() && !asleep(b);
    if (asleep(a) && b_awake_mover) {
      wake_island(bodies, island_[a], time);
      ++woken;
    } else if (asleep(b) && a_awake_mover) {
      wake_island(bodies, island_[b], time);
      ++woken;
    }
  }
  return woken;
}

std::uint64_t SleepTracker::update(std::span<RigidBody> bodies,
                                   std::span<const ContactManifold> manifolds,
                                   std::span<const BodyPair> near_pairs,
                                   std::span<const RestedPair> rested, double time) {
  if (!settings_.enabled) return 0;
  const std::size_t n = bodies.size();
  for (const ContactManifold& m : manifolds) {
    for (const Contact& c : m.contacts) {
      const double band =
          std::max(c.lambda_a + c.lambda_b,
                   bodies[m.body_a].shape().min_band() + bodies[m.body_b].shape().min_band());
      band_seen_[m.body_a] = std::max(band_seen_[m.body_a], band);
      band_seen_[m.body_b] = std::max(band_seen_[m.body_b], band);
    }
  }
  for (const RestedPair& pair : rested) {
    if (!pair.soft) continue;
    soft_seen_[pair.body_a] = 1;
    soft_seen_[pair.body_b] = 1;
  }
  if (time < next_check_) return 0;
  const double window = 0.5 * settings_.time;
  next_check_ = time + window;
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies[i].fixed() || asleep(i)) continue;
    // A window shorter than the others (the body was added or woken since the last check)
    // proves little: it is judged at a later check, from the same anchor.
    if (time - anchor_time_[i] < window) continue;
    const BodyState& s = bodies[i].state();
    const double radius = bodies[i].bounding_radius();
    const bool soft = soft_seen_[i] != 0;
    const double d = soft ? settings_.soft_bands * band_seen_[i] + settings_.soft_tolerance * radius
                          : settings_.bands * band_seen_[i] + settings_.tolerance * radius;
    const Vec2 moved = s.position - anchor_position_[i];
    const double turned = std::abs(s.angle - anchor_angle_[i]) * radius;
    const bool still = std::abs(moved.x()) <= d && std::abs(moved.y()) <= d && turned <= d;
    still_windows_[i] = still ? still_windows_[i] + 1 : 0;
    soft_judged_[i] = soft ? 1 : 0;
    anchor(bodies[i], i, time);
  }

  islands_.reset(n);
  for (const BodyPair& pair : near_pairs) {
    if (bodies[pair.a].fixed() || bodies[pair.b].fixed() || asleep(pair.a) || asleep(pair.b)) {
      continue;
    }
    islands_.unite(pair.a, pair.b);
  }
  // An island sleeps when none of its bodies is restless: each had two still windows in a row,
  // or soft_windows when its last window was a soft one.
  restless_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies[i].fixed() || asleep(i)) continue;
    const int needed = soft_judged_[i] != 0 ? std::max(settings_.soft_windows, 2) : 2;
    if (still_windows_[i] < needed) restless_[islands_.root(i)] = 1;
  }
  std::uint64_t slept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies[i].fixed() || asleep(i)) continue;
    const std::size_t root = islands_.root(i);
    if (restless_[root] != 0) continue;
    if (root == i) ++slept;
    asleep_[i] = 1;
    island_[i] = root;
    BodyState s = bodies[i].state();
    s.velocity = Vec2::Zero();
    s.angular_velocity = 0.0;
    bodies[i].set_state(s);
  }
  return slept;
}

void SleepTracker::save(ByteWriter& out) const {
  out.u64(asleep_.size());
  for (std::size_t i = 0; i < asleep_.size(); ++i) {
    out.u8(asleep_[i]);
    out.u64(island_[i]);
    out.f64(anchor_position_[i].x());
    out.f64(anchor_position_[i].y());
    out.f64(anchor_angle_[i]);
    out.f64(anchor_time_[i]);
    out.i64(still_windows_[i]);
    out.f64(band_seen_[i]);
    out.u8(soft_seen_[i]);
    out.u8(soft_judged_[i]);
  }
  out.f64(next_check_);
}

void SleepTracker::restore(ByteReader& in, std::size_t bodies) {
  if (in.u64() != bodies) throw ByteStreamError("sleep records for another number of bodies");
  asleep_.assign(bodies, 0);
  island_.assign(bodies, 0);
  anchor_position_.assign(bodies, Vec2::Zero());
  anchor_angle_.assign(bodies, 0.0);
  anchor_time_.assign(bodies, 0.0);
  still_windows_.assign(bodies, 0);
  band_seen_.assign(bodies, 0.0);
  soft_seen_.assign(bodies, 0);
  soft_judged_.assign(bodies, 0);
  for (std::size_t i = 0; i < bodies; ++i) {
    asleep_[i] = in.u8();
    island_[i] = in.u64();
    if (island_[i] >= bodies) throw ByteStreamError("a sleeping island past the last body");
    const double x = in.f64();
    anchor_position_[i] = Vec2(x, in.f64());
    anchor_angle_[i] = in.f64();
    anchor_time_[i] = in.f64();
    still_windows_[i] = static_cast<int>(in.i64());
    band_seen_[i] = in.f64();
    soft_seen_[i] = in.u8() != 0 ? 1 : 0;
    soft_judged_[i] = in.u8() != 0 ? 1 : 0;
  }
  next_check_ = in.f64();
}

}  // namespace rugosim
