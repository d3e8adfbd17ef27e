// Impacts located in time (WorldSettings::converging_contacts): a pair that arrives within its
// bands faster than impact_speed is backed off to where it arrived, as a crossing is
// (world_back_off.cpp), and gets its collision there. Without it the impulse lands where the
// step's end finds the contact, at a time and a depth in the band set by where the step happens
// to land, so errors do not fall steadily with the step (docs/accuracy/convergence.md).
#include <algorithm>
#include <utility>
#include <vector>

#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/world.h"
#include "engine/dynamics/world_crossings.h"

namespace rugosim {

void World::mark_start_contacts(const std::vector<ContactManifold>& start, bool new_step) {
  if (new_step) located_.clear();
  start_contacts_.clear();
  if (!settings_.converging_contacts) return;
  for (const ContactManifold& m : start) {
    if (m.state() == PairState::kContact) start_contacts_.emplace_back(m.body_a, m.body_b);
  }
  std::sort(start_contacts_.begin(), start_contacts_.end());
}

bool World::arrives_fast(const ContactManifold& m) const {
  const RigidBody& a = bodies_[m.body_a];
  const RigidBody& b = bodies_[m.body_b];
  ResolutionSettings statics;  // only g_n and the band are read
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

bool World::overshoots(const std::vector<ContactManifold>& manifolds,
                       std::vector<std::pair<std::size_t, std::size_t>>* arriving) const {
  if (arriving != nullptr) arriving->clear();
  bool any = world_detail::any_crossing(manifolds);
  if (!settings_.converging_contacts) return any;
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kContact) continue;
    const std::pair<std::size_t, std::size_t> pair(m.body_a, m.body_b);
    if (std::binary_search(start_contacts_.begin(), start_contacts_.end(), pair)) continue;
    if (std::binary_search(located_.begin(), located_.end(), pair)) continue;
    if (!arrives_fast(m)) continue;  // slow arrivals rest from the next step
    any = true;
    if (arriving != nullptr) arriving->push_back(pair);
  }
  return any;
}

void World::locate(const std::vector<std::pair<std::size_t, std::size_t>>& arriving) {
  located_.insert(located_.end(), arriving.begin(), arriving.end());
  std::sort(located_.begin(), located_.end());
  located_.erase(std::unique(located_.begin(), located_.end()), located_.end());
}

}  // namespace rugosim
