#include "engine/dynamics/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "engine/collision/touching.h"
#include "engine/core/disjoint_sets.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/free_flight.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/overlap_depth.h"
#include "engine/dynamics/world_crossings.h"

namespace rugosim {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

using world_detail::any_crossing;
using world_detail::BodyPairKey;
using world_detail::crossing_pairs;

World::World(WorldSettings settings)
    : settings_(std::move(settings)),
      pipeline_(settings_.narrow_phase),
      sleep_(settings_.sleep),
      locator_(settings_.narrow_phase) {
  if (!settings_.gravity.allFinite()) throw std::invalid_argument("gravity must be finite");
  if (!(std::isfinite(settings_.friction_gain) && settings_.friction_gain >= 0.0)) {
    throw std::invalid_argument("friction_gain must be finite and >= 0 (1/m)");
  }
  if (!(settings_.min_step > 0.0 && settings_.min_step <= settings_.max_step &&
        std::isfinite(settings_.max_step))) {
    throw std::invalid_argument("steps must satisfy 0 < min_step <= max_step < inf (s)");
  }
  if (settings_.rest_stride < 1 || settings_.rest_stride > kMaxRestStride) {
    throw std::invalid_argument("rest_stride must be in [1, " + std::to_string(kMaxRestStride) +
                                "]");
  }
  if (!(settings_.rest_depth > 0.0 && settings_.rest_depth < 1.0)) {
    throw std::invalid_argument("rest_depth must be in (0, 1)");
  }
  if (settings_.max_bisections <= 0 || settings_.max_resolution_passes <= 0 ||
      settings_.rest_sweeps <= 0) {
    throw std::invalid_argument(
        "max_bisections, max_resolution_passes and rest_sweeps must be > 0");
  }
  if (!(settings_.resolved_gap_fraction >= 0.0 && settings_.resolved_gap_fraction < 1.0)) {
    throw std::invalid_argument("resolved_gap_fraction must be in [0, 1)");
  }
  const NarrowPhaseSettings& narrow = settings_.narrow_phase;
  if (!(narrow.relative_accuracy > 0.0 && narrow.relative_accuracy < 1.0) ||
      narrow.seed_iterations <= 0 || narrow.max_depth <= 0 || narrow.max_cells <= 0) {
    throw std::invalid_argument(
        "narrow phase: relative_accuracy must be in (0, 1) and the counts > 0");
  }
  if (settings_.threads < 1 || settings_.threads > kMaxThreads) {
    throw std::invalid_argument("threads must be in [1, " + std::to_string(kMaxThreads) + "]");
  }
  pool_ = OwnedThreadPool(settings_.threads);
  if (!(settings_.sleep.time >= 0.0 && std::isfinite(settings_.sleep.time) &&
        settings_.sleep.tolerance >= 0.0 && std::isfinite(settings_.sleep.tolerance) &&
        settings_.sleep.bands >= 0.0 && std::isfinite(settings_.sleep.bands) &&
        settings_.sleep.soft_bands >= 0.0 && std::isfinite(settings_.sleep.soft_bands) &&
        settings_.sleep.soft_tolerance >= 0.0 && std::isfinite(settings_.sleep.soft_tolerance) &&
        settings_.sleep.soft_windows >= 1)) {
    throw std::invalid_argument(
        "sleep time (s), bands and tolerance (soft ones too) must be finite and >= 0, and "
        "soft_windows >= 1");
  }
}

std::size_t World::add_body(RigidBody body, std::string name) {
  bodies_.push_back(std::move(body));
  names_.push_back(std::move(name));
  sleep_.track(bodies_, time_);
  contacts_known_ = false;
  return bodies_.size() - 1;
}

void World::set_members(std::vector<std::size_t> members) {
  for (const std::size_t i : members_)
    moving_[i] = 0;
  members_ = std::move(members);
  for (const std::size_t i : members_)
    moving_[i] = 1;
}

void World::save_start() {
  for (const std::size_t i : members_)
    start_[i] = bodies_[i].state();
}

void World::place_at(double dt) {
  for (const std::size_t i : members_)
    bodies_[i].set_state(free_flight(start_[i], settings_.gravity, dt));
}

void World::detect() {
  placed_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    placed_[i].shape = &bodies_[i].shape();
    placed_[i].placement = bodies_[i].placement();
    placed_[i].fixed = bodies_[i].fixed();
    // A body that does not move in this sub-step is tested only against bodies that do, as
    // the broad phase treats sleeping bodies.
    placed_[i].asleep = !bodies_[i].fixed() && moving_[i] == 0;
    placed_[i].motion_per_step = placed_[i].asleep || bodies_[i].fixed()
                                     ? 0.0
                                     : bodies_[i].boundary_speed() * settings_.max_step;
  }
  const auto start = std::chrono::steady_clock::now();
  pipeline_.detect(placed_, pool_.get(), detected_);
  detected_pairs_ = pipeline_.near_pairs();
  detect_containment();
  profile_.detection += seconds_since(start);
}

void World::detect_containment() {
  containment_.resize(bodies_.size());
  const auto samples = [&](std::size_t i) -> const ContainmentSamples& {
    if (!containment_[i]) containment_[i] = containment_samples(bodies_[i]);
    return *containment_[i];
  };
  const auto key = [](std::size_t a, std::size_t b) { return std::make_pair(a, b); };
  std::size_t m = 0;  // detected_ and the near pairs are both in (a, b) order
  for (const BodyPair& pair : detected_pairs_) {
    while (m < detected_.size() &&
           key(detected_[m].body_a, detected_[m].body_b) < key(pair.a, pair.b)) {
      ++m;
    }
    if (m < detected_.size() && detected_[m].body_a == pair.a && detected_[m].body_b == pair.b) {
      continue;  // in contact or crossing: not nested
    }
    for (const auto& [inner, outer] : {key(pair.a, pair.b), key(pair.b, pair.a)}) {
      // The inner centroid lies in the inner curve's hull, so within the outer body's disc.
      const RigidBody& in = bodies_[inner];
      const RigidBody& out = bodies_[outer];
      if ((in.state().position - out.state().position).norm() > out.bounding_radius()) continue;
      if (!lies_inside(in, samples(inner), out, samples(outer)).value_or(false)) continue;
      ContactManifold nested;
      nested.body_a = pair.a;
      nested.body_b = pair.b;
      nested.intersections.push_back({0, 0, 0.0, 0.0, in.world_point(in.curve().point(0, 0.0))});
      detected_.insert(detected_.begin() + static_cast<std::ptrdiff_t>(m), std::move(nested));
      ++m;
      break;
    }
  }
}

void World::record_first_crossing(const std::vector<ContactManifold>& manifolds, double time) {
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kIntersecting) continue;
    const std::size_t a = std::min(m.body_a, m.body_b);
    const std::size_t b = std::max(m.body_a, m.body_b);
    first_crossing_ = CrossingRecord{time, a, b, sampled_overlap_depth(bodies_[a], bodies_[b])};
    return;
  }
}

void World::resolve(const std::vector<ContactManifold>& manifolds, double time) {
  const ResolutionSettings resolution{settings_.gravity, settings_.friction_gain,
                                      settings_.max_resolution_passes, settings_.max_step,
                                      settings_.resolved_gap_fraction, rest_step_, rested_,
                                      settings_.rest_depth, settings_.rest_sweeps,
                                      // Slow approaches are left to mid-step rest
                                      // only where it runs (not in a withdrawn step).
                                      settings_.converging_contacts && rest_step_ > 0.0};
  ++stats_.steps;
  if (any_crossing(manifolds)) {
    ++stats_.crossings;
    if (!first_crossing_) record_first_crossing(manifolds, time);
  }
  stats_.islands_woken += sleep_.wake_touched(bodies_, manifolds, time);
  const auto start = std::chrono::steady_clock::now();
  const ResolutionCounts counts = resolver_.resolve(bodies_, manifolds, resolution, time,
                                                    settings_.record_events ? &events_ : nullptr);
  profile_.resolution += seconds_since(start);
  stats_.collisions += counts.collisions;
  stats_.contacts += counts.contacts;
  stats_.passes += counts.passes;
  if (counts.passes_exhausted) {
    ++stats_.pass_fallbacks;
    ++stats_.fallbacks;
  }
  stats_.rigid_clusters += counts.rigid_clusters;
  if (counts.still_approaching) ++stats_.unresolved_states;
}

void World::rest_at_mid_step(const std::vector<ContactManifold>& manifolds, double h) {
  rest_step_ = 0.0;
  rested_.clear();
  if (!settings_.mid_step_rest || rest_withdrawn_) return;
  rest_step_ = h;
  // With the soft solve, its islands (soft_rest_island and up, bands wide enough for its
  // springs) rest softly and the rest by the mid-step solve; islands share no pair of moving
  // bodies, so the two never meet.
  std::span<const std::uint8_t> hard_moves = moving_;
  std::vector<RestedPair> soft_rested;
  std::vector<std::uint8_t> hard_only;
  if (settings_.soft_rest_substeps > 0) {
    const std::vector<std::uint8_t> soft_moves =
        soft_rest_movers(moving_, manifolds, settings_.soft_rest_island,
                         soft_rest_min_band(settings_.gravity, settings_.soft_rest_hertz));
    SoftRestSettings soft;
    soft.gravity = settings_.gravity;
    soft.friction_gain = settings_.friction_gain;
    soft.rest_depth = settings_.rest_depth;
    soft.substeps = settings_.soft_rest_substeps;
    soft.hertz = settings_.soft_rest_hertz;
    SoftRestCounts counts = rest_softly(bodies_, soft_moves, manifolds, h, soft, soft_memory_);
    soft_rested = std::move(counts.rested);
    end_velocities_ = std::move(counts.end);
    stats_.rest_contacts += counts.contacts;
    hard_only.assign(moving_.size(), 0);
    for (std::size_t i = 0; i < moving_.size(); ++i)
      hard_only[i] = moving_[i] != 0 && soft_moves[i] == 0 ? 1 : 0;
    hard_moves = hard_only;
  }
  const MidStepRestSettings rest{
      settings_.gravity, settings_.friction_gain, settings_.rest_depth,
      rest_sweep_settings(settings_.gravity, settings_.max_step, settings_.rest_sweeps),
      settings_.converging_contacts};
  MidStepRestCounts counts = rugosim::rest_at_mid_step(bodies_, hard_moves, manifolds, h, rest);
  if (soft_rested.empty()) {
    rested_ = std::move(counts.rested);  // the mid-step solve alone: no copy on its path
  } else {
    // Both lists follow the manifolds' (body_a, body_b) order.
    rested_.reserve(counts.rested.size() + soft_rested.size());
    std::merge(counts.rested.begin(), counts.rested.end(), soft_rested.begin(), soft_rested.end(),
               std::back_inserter(rested_), [](const RestedPair& x, const RestedPair& y) {
                 return std::tie(x.body_a, x.body_b) < std::tie(y.body_a, y.body_b);
               });
  }
  stats_.rest_contacts += counts.contacts;
  stats_.rest_sweeps += counts.sweeps;
  if (!counts.converged) ++stats_.rest_unconverged;
}

void World::rest_and_place(const std::vector<ContactManifold>& manifolds, double h) {
  end_velocities_.clear();
  rest_at_mid_step(manifolds, h);
  place_rested(h);
}

double World::rest_for_step(double h) {
  end_velocities_.clear();
  if (settings_.soft_rest_substeps == 0 || !settings_.mid_step_rest || h <= settings_.max_step) {
    rest_at_mid_step(manifolds_, h);
    return h;
  }
  // A rest step was granted on the velocities before the solve (StepPlanner::gentle_step); the
  // soft solve's push can pivot a body so that a far corner then moves further than the step
  // allows (a two-box stack rocked so, research §8.18). Such a step is solved again, halved.
  const SoftRestMemory kept = soft_memory_;
  const double g = settings_.gravity.norm();
  for (;;) {
    rest_at_mid_step(manifolds_, h);
    if (h <= settings_.max_step) return h;
    const bool gentle =
        std::all_of(end_velocities_.begin(), end_velocities_.end(), [&](const EndVelocity& e) {
          // The body's placement velocity (soft_rest.h) sweeps its whole move over h; the pair
          // limit gentle_step grants it against a body of its own bands.
          const RigidBody& b = bodies_[e.body];
          return b.boundary_speed() * h + 0.5 * g * h * h <=
                 kRestBandShare * 2.0 * b.shape().least_band();
        });
    if (gentle) return h;
    ++stats_.soft_rest_retries;
    for (const std::size_t i : members_)
      bodies_[i].set_state(before_rest_[i]);
    soft_memory_ = kept;
    end_velocities_.clear();
    h = std::max(settings_.max_step, 0.5 * h);
  }
}

void World::place_rested(double h) {
  save_start();
  place_at(h);
  for (const EndVelocity& e : end_velocities_) {
    BodyState s = bodies_[e.body].state();
    s.velocity = e.velocity;
    s.angular_velocity = e.angular_velocity;
    bodies_[e.body].set_state(s);
  }
}

double World::step(double h) {
  std::vector<std::size_t> movers;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!bodies_[i].fixed() && !sleep_.asleep(i)) movers.push_back(i);
  }
  stats_.body_steps += movers.size();
  set_members(std::move(movers));
  rest_withdrawn_ = false;
  if (settings_.mid_step_rest) {
    before_rest_.resize(bodies_.size());
    for (const std::size_t i : members_)
      before_rest_[i] = bodies_[i].state();
  }
  mark_start_contacts(manifolds_, /*new_step=*/true);
  h = rest_for_step(h);
  place_rested(h);
  detect();
  std::vector<BodyPairKey> arriving;
  if (!overshoots(detected_, &arriving)) {
    consecutive_fallbacks_ = 0;
    // The detection's scratch becomes the state's record (the next detection overwrites it).
    std::swap(manifolds_, detected_);
    std::swap(near_pairs_, detected_pairs_);
    resolve(manifolds_, time_ + h);
    return h;
  }

  // Islands of the trial: movers linked by near pairs. Those holding a crossing back off
  // alone; the rest keep the whole step (DESIGN.md: a collision in one pile must not shorten
  // every other body's step).
  DisjointSets islands;
  islands.reset(bodies_.size());
  for (const BodyPair& pair : detected_pairs_) {
    if (moving_[pair.a] != 0 && moving_[pair.b] != 0) islands.unite(pair.a, pair.b);
  }
  std::vector<std::uint8_t> crossing_root(bodies_.size(), 0);
  std::vector<BodyPairKey> backing = crossing_pairs(detected_);
  // Impacts to locate back off too.
  backing.insert(backing.end(), arriving.begin(), arriving.end());
  for (const auto& [a, b] : backing) {
    if (moving_[a] != 0) crossing_root[islands.root(a)] = 1;
    if (moving_[b] != 0) crossing_root[islands.root(b)] = 1;
  }
  join_islands_within_reach(islands, crossing_root, h);
  std::vector<std::size_t> crossing_members;
  std::vector<std::uint8_t> in_crossing(bodies_.size(), 0);
  for (const std::size_t i : members_) {
    if (crossing_root[islands.root(i)] != 0) {
      crossing_members.push_back(i);
      in_crossing[i] = 1;
    }
  }
  // The other islands are accepted at h, with the manifolds and pairs that do not involve a
  // crossing island (those are found again as the crossing islands move).
  std::vector<ContactManifold> outside;
  for (const ContactManifold& m : detected_) {
    if (in_crossing[m.body_a] == 0 && in_crossing[m.body_b] == 0) outside.push_back(m);
  }
  std::vector<BodyPair> outside_pairs;
  for (const BodyPair& pair : detected_pairs_) {
    if (in_crossing[pair.a] == 0 && in_crossing[pair.b] == 0) outside_pairs.push_back(pair);
  }
  if (crossing_members.size() < members_.size()) resolve(outside, time_ + h);

  set_members(std::move(crossing_members));
  // A crossing island whose slow contacts got mid-step impulses goes on without them, from its
  // state before them, as if mid-step rest were off for this step: where the impulses did not
  // converge (a light crate under a heavy one: Gauss-Seidel sweeps carry a stack's weight down
  // slowly) they can leave a contact closing faster than its gap allows, and the back-off,
  // bisecting the same velocities, then finds no state short of the crossing (stress seeds
  // 1, 5, 13, 19, 25 with mid-step rest forced: thousands of accepted crossings). Micro-
  // collisions answer such an island's contacts for the rest of the step, as they always did.
  // Where no member got an impulse the trial stands as it is (no second trial of the same move).
  // An island backing off only to locate an impact keeps its impulses: nothing crossed.
  bool withdraw_rest = false;
  if (rest_step_ > 0.0 && any_crossing(detected_)) {
    rest_withdrawn_ = true;
    for (const std::size_t i : members_) {
      const BodyState& before = before_rest_[i];
      const BodyState& start = start_[i];
      if (start.velocity != before.velocity || start.angular_velocity != before.angular_velocity)
        withdraw_rest = true;
    }
  }
  if (withdraw_rest) {
    ++stats_.rest_withdrawn;
    for (const std::size_t i : members_)
      bodies_[i].set_state(before_rest_[i]);
  }
  advance_crossing_members(h, /*trial_crosses=*/!withdraw_rest);
  rest_withdrawn_ = false;

  // The state at the end of the step: both sets of manifolds, in the pipeline's order.
  manifolds_ = std::move(outside);
  for (const ContactManifold& m : accepted_) {
    if (in_crossing[m.body_a] != 0 || in_crossing[m.body_b] != 0) manifolds_.push_back(m);
  }
  std::sort(manifolds_.begin(), manifolds_.end(),
            [](const ContactManifold& x, const ContactManifold& y) {
              return std::tie(x.body_a, x.body_b) < std::tie(y.body_a, y.body_b);
            });
  near_pairs_ = std::move(outside_pairs);
  for (const BodyPair& pair : accepted_pairs_) {
    if (in_crossing[pair.a] != 0 || in_crossing[pair.b] != 0) near_pairs_.push_back(pair);
  }
  std::sort(near_pairs_.begin(), near_pairs_.end(), [](const BodyPair& x, const BodyPair& y) {
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return h;
}

bool World::near_anything() const {
  return std::any_of(near_pairs_.begin(), near_pairs_.end(), [&](const BodyPair& p) {
    const auto moves = [&](std::size_t i) { return !bodies_[i].fixed() && !sleep_.asleep(i); };
    return moves(p.a) || moves(p.b);
  });
}

double World::next_step(double remaining) {
  awake_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    awake_[i] = !bodies_[i].fixed() && !sleep_.asleep(i) ? 1 : 0;
  // Apart, a step runs as far as nothing can meet: to the target time, or else to the furthest
  // point of the grid of max_step steps from the last target that halving finds (so that near
  // contact the steps fall where they always did).
  if (remaining > settings_.max_step && !near_anything()) {
    // A step ends at the first point of the grid past the next sleep check, as short steps would,
    // so that resting bodies are judged as often.
    double limit = remaining;
    const double until_check = sleep_.next_check() - time_;
    if (settings_.sleep.enabled && until_check < remaining) {
      const double grid_steps = std::max(1.0, std::ceil(until_check / settings_.max_step));
      limit = std::min(remaining, grid_steps * settings_.max_step);
    }
    const double steps = std::floor(limit / settings_.max_step);
    for (double k = steps; k >= 2.0; k = std::floor(0.5 * k)) {
      const double h = k == steps ? limit : k * settings_.max_step;
      if (planner_.nothing_can_meet(bodies_, awake_, settings_.gravity, h)) {
        ++stats_.free_steps;
        return h;
      }
    }
  }
  // Near contact, a step may still be long when every pair that can meet in it moves gently:
  // then contacts are found no deeper in their bands than impacts at max_step find them.
  if (settings_.rest_stride > 1 && remaining > settings_.max_step) {
    const double longest = std::min(remaining, settings_.rest_stride * settings_.max_step);
    const double h =
        planner_.gentle_step(bodies_, awake_, settings_.gravity, longest, kRestBandShare);
    if (h > settings_.max_step) {
      ++stats_.rest_steps;
      return planner_.tunnel_free(bodies_, awake_, settings_.gravity, h, settings_.min_step);
    }
  }
  return planner_.tunnel_free(bodies_, awake_, settings_.gravity,
                              std::min(settings_.max_step, remaining), settings_.min_step);
}

void World::detect_initial_contacts() {
  // Bodies placed in each other's bands rest from the first step, as they would from any later
  // one: without this the first step is free fall onto the contact, and whether its approach
  // (g·h) counts as resolved is a rounding of g·h against itself, so a hop fires at some steps
  // and not at others (docs/accuracy/convergence.md).
  std::vector<std::size_t> movers;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!bodies_[i].fixed() && !sleep_.asleep(i)) movers.push_back(i);
  }
  set_members(std::move(movers));
  detect();
  std::swap(manifolds_, detected_);
  std::swap(near_pairs_, detected_pairs_);
  contacts_known_ = true;
}

void World::advance_to(double t) {
  const auto start = std::chrono::steady_clock::now();
  const double detection = profile_.detection, resolution = profile_.resolution;
  moving_.resize(bodies_.size(), 0);
  start_.resize(bodies_.size());
  if (!contacts_known_ && time_ < t) detect_initial_contacts();
  while (time_ < t && !stop_requested()) {
    if (!sleep_.any_awake_mover(bodies_)) {
      // Nothing can move until something is woken from outside: no steps to take.
      time_ = t;
      ++stats_.idle_jumps;
      break;
    }
    const double remaining = t - time_;
    const double h = step(next_step(remaining));
    // Land exactly on t rather than a rounding short of it.
    time_ = h == remaining ? t : time_ + h;
    stats_.islands_slept += sleep_.update(bodies_, manifolds_, near_pairs_, rested_, time_);
  }
  stats_.sim_time = time_;
  profile_.stepping +=
      seconds_since(start) - (profile_.detection - detection) - (profile_.resolution - resolution);
}

}  // namespace rugosim
