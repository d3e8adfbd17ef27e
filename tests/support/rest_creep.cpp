#include "support/rest_creep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rugosim::testing {

std::vector<double> narrowest_contact_bands(const World& world) {
  std::vector<double> band(world.body_count(), std::numeric_limits<double>::infinity());
  for (const ContactManifold& m : world.manifolds()) {
    if (m.state() != PairState::kContact) continue;
    for (const Contact& c : m.contacts) {
      band[m.body_a] = std::min(band[m.body_a], c.lambda_a + c.lambda_b);
      band[m.body_b] = std::min(band[m.body_b], c.lambda_a + c.lambda_b);
    }
  }
  return band;
}

void RestCreepTracker::record(const World& world) {
  std::vector<Sample> frame(world.body_count());
  movable_.assign(world.body_count(), false);
  const std::vector<double> band = narrowest_contact_bands(world);
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    frame[i].position = world.body(i).state().position;
    frame[i].asleep = world.asleep(i);
    frame[i].narrowest_band = std::isinf(band[i]) ? 0.0 : band[i];
    movable_[i] = !world.body(i).fixed();
  }
  for (const ContactManifold& m : world.manifolds()) {
    if (m.state() != PairState::kContact) continue;
    frame[m.body_a].partners.push_back(m.body_b);
    frame[m.body_b].partners.push_back(m.body_a);
  }
  for (Sample& s : frame)
    std::sort(s.partners.begin(), s.partners.end());
  frames_.push_back(std::move(frame));
}

RestCreep RestCreepTracker::result() const {
  RestCreep out;
  if (frames_.empty()) return out;
  const std::size_t last = frames_.size() - 1;
  for (std::size_t i = 0; i < movable_.size(); ++i) {
    if (!movable_[i] || !frames_[last][i].asleep) continue;
    // The last frame it was awake at (a sleeping body's contacts need not be detected).
    std::size_t k = last;
    while (k > 0 && frames_[k][i].asleep)
      --k;
    if (frames_[k][i].asleep || k < static_cast<std::size_t>(window_)) continue;
    const std::size_t first = k - static_cast<std::size_t>(window_);
    const Sample& end = frames_[k][i];
    bool rested = !end.partners.empty();
    for (std::size_t f = first; f <= k && rested; ++f)
      rested = frames_[f][i].partners == end.partners;
    if (!rested) continue;
    ++out.resting;
    const double displacement = (end.position - frames_[first][i].position).norm();
    const double ratio = displacement / end.narrowest_band;
    if (ratio > 1.0) ++out.over_band;
    if (ratio > out.worst_ratio) {
      out.worst_ratio = ratio;
      out.worst_displacement = displacement;
      out.worst_body = i;
    }
  }
  return out;
}

}  // namespace rugosim::testing
