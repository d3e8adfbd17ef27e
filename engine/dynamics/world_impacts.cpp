// Impacts located in time (WorldSettings::converging_contacts): a pair that arrives within its
// bands faster than impact_speed is backed off to where it arrived, as a crossing is
// (world_back_off.cpp), and gets its collision there. Without it the impulse lands where the
// step's end finds the contact, at a time and a depth in the band set by where the step happens
// to land, so errors do not fall steadily with the step (docs/accuracy/convergence.md).
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/free_flight.h"
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

std::optional<double> World::locate_arrivals(double dt_full, double* hi) {
  std::vector<std::pair<std::size_t, std::size_t>> arriving;
  overshoots(detected_, &arriving);
  // Bisecting the island's detection would find the same time: the island overshoots from the
  // first of these arrivals on. One pair's narrow phase costs a fraction of the island's (a
  // pile is one island: 200 bodies detected 20 times per impact made the converging rules cost
  // 11 times the rest of the step on pile_200), so each pair is bisected alone and the island
  // is detected once, where the first one arrived.
  double first = dt_full;
  ContactManifold m;
  for (const auto& [a, b] : arriving) {
    LeafPairCache cache;  // the pair's tree query, kept across its bisections
    const auto place = [&](std::size_t i, double dt) {
      if (moving_[i] != 0) bodies_[i].set_state(free_flight(start_[i], settings_.gravity, dt));
    };
    const double margin =
        3.0 * (bodies_[a].boundary_speed() + bodies_[b].boundary_speed()) * dt_full;
    double lo = 0.0, up = dt_full;
    for (int i = 0; i < settings_.max_bisections && up - lo > settings_.min_step; ++i) {
      const double mid = lo + 0.5 * (up - lo);
      place(a, mid);
      place(b, mid);
      locator_.collide(bodies_[a].shape(), bodies_[a].placement(), bodies_[b].shape(),
                       bodies_[b].placement(), m, &cache, margin);
      m.body_a = a;
      m.body_b = b;
      ++stats_.bisections;
      const PairState state = m.state();
      if (state == PairState::kIntersecting || (state == PairState::kContact && arrives_fast(m))) {
        up = mid;
      } else {
        lo = mid;
      }
    }
    first = std::min(first, up);
  }
  place_at(first);
  detect();
  ++stats_.bisections;
  *hi = first;
  std::vector<std::pair<std::size_t, std::size_t>> here;
  const bool over = overshoots(detected_, &here);
  const bool expected = std::includes(arriving.begin(), arriving.end(), here.begin(), here.end());
  if (over && !here.empty() && expected && !world_detail::any_crossing(detected_)) {
    accepted_ = detected_;
    accepted_pairs_ = detected_pairs_;
    consecutive_fallbacks_ = 0;
    locate(here);
    return first;
  }
  if (!over) {
    // The island does not overshoot where the pair did (cannot happen while the pair's
    // manifold is the island's): back_off bisects from the trial's end.
    place_at(dt_full);
    detect();
    *hi = dt_full;
  }
  return std::nullopt;
}

}  // namespace rugosim
