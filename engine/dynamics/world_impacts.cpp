// Impacts located in time (WorldSettings::converging_contacts). A pair that arrives within its
// bands faster than impact_speed is backed off to where it arrived, as a crossing is
// (world_back_off.cpp), and gets its collision there; a contact that sinks past deep_share of
// its band within a step is backed off to where it got there and gets its micro-collision.
// Without it both impulses land where the step's end finds the contact, at a time and a depth
// set by where the step happens to land, so errors do not fall steadily with the step
// (docs/accuracy/convergence.md).
#include <algorithm>
#include <utility>
#include <vector>

#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/world.h"
#include "engine/dynamics/world_crossings.h"

namespace rugosim {

double World::depth_share(const ContactManifold& m) const {
  if (m.state() != PairState::kContact) return 0.0;
  const double min_band =
      bodies_[m.body_a].shape().min_band() + bodies_[m.body_b].shape().min_band();
  double share = 0.0;
  for (const Contact& c : m.contacts) {
    const double band = std::max(c.lambda_a + c.lambda_b, min_band);
    share = std::max(share, std::clamp((band - c.distance) / band, 0.0, 1.0));
  }
  return share;
}

void World::mark_start_depths(const std::vector<ContactManifold>& start, bool new_step) {
  if (new_step) located_.clear();
  start_depths_.clear();
  if (!settings_.converging_contacts) return;
  for (const ContactManifold& m : start) {
    // −1: not within its bands at the start, so a contact now is an arrival.
    const double share = m.state() == PairState::kContact ? depth_share(m) : -1.0;
    start_depths_.push_back({{m.body_a, m.body_b}, share});
  }
  std::sort(start_depths_.begin(), start_depths_.end());
}

bool World::arrives_fast(const ContactManifold& m) const {
  const RigidBody& a = bodies_[m.body_a];
  const RigidBody& b = bodies_[m.body_b];
  ResolutionSettings statics;
  statics.gravity = settings_.gravity;
  statics.friction_gain = settings_.friction_gain;
  for (const Contact& c : m.contacts) {
    const ContactStatics k = contact_statics(a, b, c, statics);
    const double vn =
        relative_contact_velocity(contact_state(a, c.point), contact_state(b, c.point))
            .dot(c.normal);
    if (vn < -impact_speed(k)) return true;
  }
  return false;
}

bool World::overshoots(const std::vector<ContactManifold>& manifolds, ImpactPairs* impacts) const {
  if (impacts != nullptr) {
    impacts->deep.clear();
    impacts->arriving.clear();
  }
  bool any = world_detail::any_crossing(manifolds);
  if (!settings_.converging_contacts) return any;
  const double limit = deep_share(settings_.rest_depth);
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kContact) continue;
    const std::pair<std::size_t, std::size_t> pair(m.body_a, m.body_b);
    if (std::binary_search(located_.begin(), located_.end(), pair)) continue;
    const auto start =
        std::lower_bound(start_depths_.begin(), start_depths_.end(), pair,
                         [](const auto& entry, const auto& key) { return entry.first < key; });
    const double before =
        start != start_depths_.end() && start->first == pair ? start->second : -1.0;
    if (before < 0.0) {
      if (!arrives_fast(m)) continue;  // slow arrivals rest from the next step
      any = true;
      if (impacts != nullptr) impacts->arriving.push_back(pair);
    } else if (before <= limit && depth_share(m) > limit) {
      any = true;
      if (impacts != nullptr) impacts->deep.push_back(pair);
    }
  }
  return any;
}

void World::locate(const ImpactPairs& impacts) {
  answer_now_ = impacts.deep;
  located_.insert(located_.end(), impacts.deep.begin(), impacts.deep.end());
  located_.insert(located_.end(), impacts.arriving.begin(), impacts.arriving.end());
  std::sort(located_.begin(), located_.end());
  located_.erase(std::unique(located_.begin(), located_.end()), located_.end());
}

}  // namespace rugosim
