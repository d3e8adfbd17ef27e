#include "support/rest_creep.h"

#include <algorithm>
#include <limits>

namespace rugosim::testing {

void RestCreepTracker::record(const World& world) {
  std::vector<Sample> frame(world.body_count());
  movable_.assign(world.body_count(), false);
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    frame[i].position = world.body(i).state().position;
    frame[i].asleep = world.asleep(i);
    movable_[i] = !world.body(i).fixed();
  }
  for (const ContactManifold& m : world.manifolds()) {
    if (m.state() != PairState::kContact) continue;
    double band = std::numeric_limits<double>::infinity();
    for (const Contact& c : m.contacts)
      band = std::min(band, c.lambda_a + c.lambda_b);
    for (const auto& [self, other] : {std::pair{m.body_a, m.body_b}, {m.body_b, m.body_a}}) {
      Sample& s = frame[self];
      s.partners.push_back(other);
      s.narrowest_band = s.narrowest_band == 0.0 ? band : std::min(s.narrowest_band, band);
    }
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
