#include "engine/dynamics/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/free_flight.h"

namespace rugosim {
namespace {

using BodyPairKey = std::pair<std::size_t, std::size_t>;

bool any_crossing(const std::vector<ContactManifold>& manifolds) {
  return std::any_of(manifolds.begin(), manifolds.end(), [](const ContactManifold& m) {
    return m.state() == PairState::kIntersecting;
  });
}

// Sorted, since the pipeline sorts its manifolds by (body_a, body_b).
std::vector<BodyPairKey> crossing_pairs(const std::vector<ContactManifold>& manifolds) {
  std::vector<BodyPairKey> pairs;
  for (const ContactManifold& m : manifolds) {
    if (m.state() == PairState::kIntersecting) pairs.emplace_back(m.body_a, m.body_b);
  }
  return pairs;
}

// Does a pair that crossed at the rejected end of the step touch within its band here?
bool touches_crossing_pair(const std::vector<ContactManifold>& manifolds,
                           const std::vector<BodyPairKey>& pairs) {
  return std::any_of(manifolds.begin(), manifolds.end(), [&](const ContactManifold& m) {
    return m.state() == PairState::kContact &&
           std::binary_search(pairs.begin(), pairs.end(), BodyPairKey(m.body_a, m.body_b));
  });
}

}  // namespace

World::World(WorldSettings settings) : settings_(std::move(settings)), sleep_(settings_.sleep) {
  if (!settings_.gravity.allFinite()) throw std::invalid_argument("gravity must be finite");
  if (!(std::isfinite(settings_.friction_gain) && settings_.friction_gain >= 0.0)) {
    throw std::invalid_argument("friction_gain must be finite and >= 0 (1/m)");
  }
  if (!(settings_.min_step > 0.0 && settings_.min_step <= settings_.max_step &&
        std::isfinite(settings_.max_step))) {
    throw std::invalid_argument("steps must satisfy 0 < min_step <= max_step < inf (s)");
  }
  if (settings_.max_bisections <= 0 || settings_.max_resolution_passes <= 0) {
    throw std::invalid_argument("max_bisections and max_resolution_passes must be > 0");
  }
  if (!(settings_.sleep.time >= 0.0 && std::isfinite(settings_.sleep.time) &&
        settings_.sleep.tolerance >= 0.0 && std::isfinite(settings_.sleep.tolerance) &&
        settings_.sleep.bands >= 0.0 && std::isfinite(settings_.sleep.bands))) {
    throw std::invalid_argument("sleep time (s), bands and tolerance must be finite and >= 0");
  }
}

std::size_t World::add_body(RigidBody body, std::string name) {
  bodies_.push_back(std::move(body));
  names_.push_back(std::move(name));
  sleep_.track(bodies_);
  return bodies_.size() - 1;
}

void World::place_at(double dt) {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (bodies_[i].fixed() || sleep_.asleep(i)) continue;
    bodies_[i].set_state(free_flight(start_[i], settings_.gravity, dt));
  }
}

const std::vector<ContactManifold>& World::detect() {
  placed_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    placed_[i].shape = &bodies_[i].shape();
    placed_[i].placement = bodies_[i].placement();
    placed_[i].fixed = bodies_[i].fixed();
    placed_[i].asleep = sleep_.asleep(i);
  }
  detected_ = pipeline_.detect(placed_);
  detected_pairs_ = pipeline_.near_pairs();
  return detected_;
}

double World::back_off(double h) {
  double lo = 0.0;
  double hi = h;
  std::vector<BodyPairKey> pairs = crossing_pairs(detected_);
  std::vector<ContactManifold> lo_manifolds;
  std::vector<BodyPair> lo_pairs;
  for (int i = 0; i < settings_.max_bisections && hi - lo > settings_.min_step; ++i) {
    const double mid = lo + 0.5 * (hi - lo);
    place_at(mid);
    detect();
    ++stats_.bisections;
    if (any_crossing(detected_)) {
      hi = mid;
      pairs = crossing_pairs(detected_);
      continue;
    }
    lo = mid;
    lo_manifolds = detected_;
    lo_pairs = detected_pairs_;
    if (touches_crossing_pair(detected_, pairs)) {
      consecutive_fallbacks_ = 0;
      manifolds_ = std::move(lo_manifolds);
      near_pairs_ = std::move(lo_pairs);
      return mid;
    }
  }
  if (lo > 0.0) {
    // No contact caught yet, but progress: the gap closes on a later step.
    place_at(lo);
    consecutive_fallbacks_ = 0;
    manifolds_ = std::move(lo_manifolds);
    near_pairs_ = std::move(lo_pairs);
    return lo;
  }
  ++stats_.fallbacks;
  if (++consecutive_fallbacks_ > kMaxConsecutiveFallbacks) {
    // Stopping the bodies did not help: accept the whole trial step, crossing, so that time
    // moves on at the normal pace (accepting only min_step would crawl).
    place_at(h);
    ++stats_.crossing_fallbacks;
    consecutive_fallbacks_ = 0;
    manifolds_ = detect();
    near_pairs_ = detected_pairs_;
    return h;
  }
  // Even min_step crosses: stop the bodies that would cross, and stay where we are.
  ++stats_.min_step_fallbacks;
  place_at(0.0);
  for (const BodyPairKey& pair : pairs) {
    for (const std::size_t i : {pair.first, pair.second}) {
      if (bodies_[i].fixed()) continue;
      BodyState s = bodies_[i].state();
      s.velocity = Vec2::Zero();
      s.angular_velocity = 0.0;
      bodies_[i].set_state(s);
    }
  }
  manifolds_ = detect();
  near_pairs_ = detected_pairs_;
  return 0.0;
}

double World::step(double h) {
  start_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    start_[i] = bodies_[i].state();
  place_at(h);
  detect();
  if (!any_crossing(detected_)) {
    manifolds_ = detected_;
    near_pairs_ = detected_pairs_;
    consecutive_fallbacks_ = 0;
    return h;
  }
  return back_off(h);
}

void World::advance_to(double t) {
  const ResolutionSettings resolution{settings_.gravity, settings_.friction_gain,
                                      settings_.max_resolution_passes, settings_.max_step};
  while (time_ < t) {
    if (!sleep_.any_awake_mover(bodies_)) {
      // Nothing can move until something is woken from outside: no steps to take.
      time_ = t;
      ++stats_.idle_jumps;
      break;
    }
    const double remaining = t - time_;
    const double h = std::min(settings_.max_step, remaining);
    const double dt = step(h);
    // Land exactly on t rather than a rounding short of it.
    time_ = dt == remaining ? t : time_ + dt;
    ++stats_.steps;
    if (any_crossing(manifolds_)) ++stats_.crossings;
    stats_.islands_woken += sleep_.wake_touched(bodies_, manifolds_);
    const ResolutionCounts counts = resolve_contacts(bodies_, manifolds_, resolution, time_,
                                                     settings_.record_events ? &events_ : nullptr);
    stats_.collisions += counts.collisions;
    stats_.contacts += counts.contacts;
    stats_.passes += counts.passes;
    if (counts.passes_exhausted) {
      ++stats_.pass_fallbacks;
      ++stats_.fallbacks;
    }
    stats_.rigid_clusters += counts.rigid_clusters;
    if (counts.still_approaching) ++stats_.unresolved_states;
    stats_.islands_slept += sleep_.update(bodies_, manifolds_, near_pairs_, time_);
  }
  stats_.sim_time = time_;
}

}  // namespace rugosim
