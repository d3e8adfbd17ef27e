// World's answer to a step whose end crosses (DESIGN.md, "Stepping"): the islands holding a
// crossing back off alone, bisecting towards the first contact (back_off), with the sub-steps
// of advance_crossing_members; islands within reach of one join it; a pair held touching at the
// edge of the touching depth is moved apart (push_touching_apart).
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "engine/collision/touching.h"
#include "engine/core/disjoint_sets.h"
#include "engine/dynamics/world.h"
#include "engine/dynamics/world_crossings.h"

namespace rugosim {

using world_detail::any_crossing;
using world_detail::BodyPairKey;
using world_detail::crossing_pairs;
using world_detail::touches_crossing_pair;

double World::back_off(double dt_full) {
  double lo = 0.0;
  double hi = dt_full;
  if (settings_.converging_contacts && !any_crossing(detected_)) {
    if (const std::optional<double> dt = locate_arrivals(dt_full, &hi)) return *dt;
  }
  std::vector<BodyPairKey> pairs = crossing_pairs(detected_);
  std::vector<BodyPairKey> arriving, arriving_here;  // impacts to locate (world_impacts.cpp)
  overshoots(detected_, &arriving);
  bool have_lo = false;
  // min_step bounds the search once it has made progress; before that, halving goes on below
  // it, down to kFinestStepShare of it (and within max_bisections): a gap thinner than the
  // closing speed times min_step (small bodies have thin bands) needs a finer step to be caught.
  const double finest = settings_.min_step * kFinestStepShare;
  for (int i = 0; i < settings_.max_bisections &&
                  (hi - lo > settings_.min_step || (!have_lo && hi - lo > finest));
       ++i) {
    const double mid = lo + 0.5 * (hi - lo);
    place_at(mid);
    detect();
    ++stats_.bisections;
    if (overshoots(detected_, &arriving_here)) {
      hi = mid;
      pairs = crossing_pairs(detected_);
      arriving.swap(arriving_here);
      continue;
    }
    lo = mid;
    accepted_ = detected_;
    accepted_pairs_ = detected_pairs_;
    have_lo = true;
    // An impact to locate is bisected down to min_step: its time is the answer's.
    if (arriving.empty() && touches_crossing_pair(detected_, pairs)) {
      consecutive_fallbacks_ = 0;
      return mid;
    }
  }
  if (pairs.empty() && !arriving.empty()) {
    // Arrivals located: answered at hi, just within their bands (lo has them outside).
    place_at(hi);
    detect();
    accepted_ = detected_;
    accepted_pairs_ = detected_pairs_;
    consecutive_fallbacks_ = 0;
    locate(arriving);
    return hi;
  }
  if (have_lo) {
    // No contact caught yet, but progress: the gap closes on a later sub-step.
    place_at(lo);
    consecutive_fallbacks_ = 0;
    return lo;
  }
  ++stats_.fallbacks;
  if (++consecutive_fallbacks_ > kMaxConsecutiveFallbacks) {
    // Stopping the bodies did not help: accept the whole move, crossing, so that time moves
    // on at the normal pace (accepting only min_step would crawl).
    place_at(dt_full);
    ++stats_.crossing_fallbacks;
    consecutive_fallbacks_ = 0;
    detect();
    accepted_ = detected_;
    accepted_pairs_ = detected_pairs_;
    return dt_full;
  }
  // Even min_step crosses: stop the members that would cross, and stay where we are.
  ++stats_.min_step_fallbacks;
  place_at(0.0);
  for (const BodyPairKey& pair : pairs) {
    for (const std::size_t i : {pair.first, pair.second}) {
      if (bodies_[i].fixed() || moving_[i] == 0) continue;
      BodyState s = bodies_[i].state();
      s.velocity = Vec2::Zero();
      s.angular_velocity = 0.0;
      bodies_[i].set_state(s);
    }
  }
  detect();
  push_touching_apart(pairs);
  accepted_ = detected_;
  accepted_pairs_ = detected_pairs_;
  return 0.0;
}

void World::push_touching_apart(const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  // A pair that touches (a contact at distance 0: reaching into each other by less than the
  // touching depth) at the state held, and crosses a rounding later even with both bodies
  // stopped, sits at the edge of that depth: no sub-step can move it, and after
  // kMaxConsecutiveFallbacks the crossing fallback would take the move across (stress seeds
  // 1389, 1393). Such a pair is moved apart along its touching contacts' mean normal by twice
  // the touching depth (a position correction of nanometres, shared by inverse mass among the
  // bodies moving in this sub-step), back inside the tolerance with room to spare.
  const bool held_crossing = any_crossing(detected_);
  std::vector<std::pair<std::size_t, BodyState>> saved;  // each moved body's state before
  for (const ContactManifold& m : detected_) {
    if (!std::binary_search(pairs.begin(), pairs.end(), std::make_pair(m.body_a, m.body_b)))
      continue;
    Vec2 normal = Vec2::Zero();
    for (const Contact& c : m.contacts) {
      if (c.distance == 0.0) normal += c.normal;
    }
    if (!(normal.norm() > 0.0)) continue;
    normal.normalize();
    // A body outside this sub-step (asleep, or in another island) is held like a fixed one.
    const auto weight = [this](std::size_t i) {
      return moving_[i] != 0 ? bodies_[i].inverse_mass() : 0.0;
    };
    const double wa = weight(m.body_a), wb = weight(m.body_b);
    if (!(wa + wb > 0.0)) continue;
    const double depth =
        kTouchingDepthRelative * std::min(bodies_[m.body_a].shape().tree().reach(),
                                          bodies_[m.body_b].shape().tree().reach());
    const Vec2 shift = 2.0 * depth * normal;  // from B towards A
    for (auto [i, share] :
         {std::make_pair(m.body_a, wa / (wa + wb)), std::make_pair(m.body_b, -wb / (wa + wb))}) {
      if (share == 0.0) continue;
      BodyState st = bodies_[i].state();
      saved.emplace_back(i, st);
      st.position += share * shift;
      bodies_[i].set_state(st);
    }
  }
  if (saved.empty()) return;
  detect();
  if (!held_crossing && any_crossing(detected_)) {
    // The push crossed some other pair: the held state is kept as it was.
    for (auto it = saved.rbegin(); it != saved.rend(); ++it)
      bodies_[it->first].set_state(it->second);
    detect();
  }
}

void World::join_islands_within_reach(DisjointSets& islands,
                                      std::vector<std::uint8_t>& crossing_root, double h) const {
  // A body's boundary and bands stay within its tree's reach of its centre of mass, and the
  // centre's free-flight path strays from the chord between its ends by at most |g|·h²/8: a
  // box around that chord, so widened, holds the body wherever it backs off to.
  const double bow = settings_.gravity.norm() * h * h / 8.0;
  const auto box_of = [&](std::size_t i, bool swept) {
    const double r = bodies_[i].shape().tree().reach() + (swept ? bow : 0.0);
    const Vec2& end = bodies_[i].state().position;
    const Vec2& begin = swept ? start_[i].position : end;
    Aabb box;
    box.extend(Vec2(begin.array() - r));
    box.extend(Vec2(begin.array() + r));
    box.extend(Vec2(end.array() - r));
    box.extend(Vec2(end.array() + r));
    return box;
  };
  std::vector<Aabb> swept(bodies_.size()), held(bodies_.size());
  for (const std::size_t i : members_) {
    swept[i] = box_of(i, true);
    held[i] = box_of(i, false);
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const std::size_t i : members_) {
      if (crossing_root[islands.root(i)] == 0) continue;
      for (const std::size_t j : members_) {
        if (crossing_root[islands.root(j)] != 0 || !swept[i].overlaps(held[j])) continue;
        crossing_root[islands.root(j)] = 1;
        grew = true;
      }
    }
  }
}

void World::advance_crossing_members(double h, bool trial_crosses) {
  double local = 0.0;  // s after time_ reached by the members
  int back_offs = 0;
  while (local < h) {
    const double dt_full = h - local;
    if (++back_offs > kMaxBackOffsPerStep) {
      // The sub-steps are crawling: the island holds where it is, in the state it reached and
      // with the impulses it got there, for the rest of the step, so that time moves on without
      // a crossing (taking the rest of the move would cross).
      consecutive_fallbacks_ = 0;
      ++stats_.stalled_steps;
      ++stats_.fallbacks;
      stats_.stalled_time += dt_full;
      return;
    }
    if (!trial_crosses) {
      rest_and_place(accepted_, dt_full);
      detect();
      if (!overshoots(detected_)) {
        accepted_ = detected_;
        accepted_pairs_ = detected_pairs_;
        consecutive_fallbacks_ = 0;
        resolve(accepted_, time_ + h);
        return;
      }
    }
    trial_crosses = false;
    const double dt = back_off(dt_full);
    local = dt == dt_full ? h : local + dt;
    resolve(accepted_, time_ + local);
    mark_start_contacts(accepted_, /*new_step=*/false);
  }
}

}  // namespace rugosim
