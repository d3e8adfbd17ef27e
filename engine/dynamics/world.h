// The World: rigid bodies advanced in time under gravity, with collisions and resting contact
// resolved by impulses (paper §4; DESIGN.md, "Dynamics").
//
// One internal step of size h (at most max_step, and never past the target time):
//  1. Every awake movable body is moved from its state at the step's start by exact free
//     flight (free_flight.h), and collision detection runs on the trial state. Without a
//     crossing, the state is accepted and its contacts get impulses (step 3).
//  2. With a crossing, the trial's islands (awake movable bodies linked by near pairs, i.e.
//     overlapping boxes) are split: islands without a crossing keep the whole step and get
//     their impulses at once; only the islands holding a crossing back off (DESIGN.md: a
//     collision in one pile must not shorten every other body's step), the rest of the world
//     held still where it is. Their move is bisected on [lo, hi] = [0, h]: a trial that
//     crosses becomes hi, one that does not becomes lo. It stops, accepting the trial, as soon
//     as a non-crossing trial has a tolerated contact on a pair that crosses at hi: the bodies
//     are then within their band, never across it. Bisection is bounded by max_bisections and,
//     once some trial did not cross, by hi − lo <= min_step (before that it goes on below
//     min_step, down to kFinestStepShare of it: a band thinner than the closing speed times
//     min_step, as small bodies have, needs it); when it runs out without such a trial, the last lo
//     is accepted if lo > 0 (the gap closes on a later sub-step). If lo = 0 (even the shortest
//     trial crosses), the fallback stops the bodies of the crossing pairs (v = 0, ω = 0) and
//     accepts the unchanged state, counted in min_step_fallbacks; after kMaxConsecutiveFallbacks
//     such fallbacks in a row the whole remaining move is accepted although it crosses, counted in
//     crossing_fallbacks and crossings, so that time always moves on. Each accepted sub-state
//     gets its impulses, and the backed-off islands sub-step on until they too reach h. An
//     island apart from the crossing ones at h, but within reach of one of their bodies
//     anywhere between its start and h, backs off with them (join_islands_within_reach): a
//     backed-off body must not meet a body held at h. A step is backed off at most
//     kMaxBackOffsPerStep times: contacts that come and go at the resolution of the narrow
//     phase, or a stack of bodies bouncing in bands a micrometre thin, could otherwise make the
//     sub-steps crawl; then the backed-off islands stay where they reached, with the impulses
//     they got there, for the rest of the step (their clock stops, counted in stalled_steps and
//     stalled_time), rather than take a move that would cross.
//  3. Contacts of an accepted state get impulses (contact_resolution.h: collisions, and
//     micro-collisions for resting contact; material mixing, gravity rules and the rigid-
//     cluster fallback are there). Sleeping islands touched by an awake body wake first.
//  0. Before each step, its length is cut so that no body can tunnel: two bodies whose boxes
//     could meet within the step (each box grown by how far the body can move in it: speed and
//     spin times the bounding radius, and gravity) move, relative to each other, at most half
//     the thinner one's thickness (RigidBody::thickness). The crossing check at the step's end
//     then sees any overlap before a body can get through to the other side (for convex
//     bodies; a concave body's thickness is an average, see RigidBody::thickness). It costs
//     nothing while every body is slow: the step is cut only when some body could move more
//     than a quarter of the thinnest body's thickness in it.
//  4. Sleeping (sleep_tracker.h): after the step, islands that have been still long enough
//     fall asleep. Sleeping bodies are not moved and pairs of them with fixed or sleeping
//     bodies are not tested; when nothing movable is awake, advance_to jumps straight to its
//     target time.
//
// Determinism: only ordered containers and a fixed order of operations, so the same bodies and
// settings give bit-identical states, events and stats.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/disjoint_sets.h"
#include "engine/core/thread_pool.h"
#include "engine/core/types.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/containment.h"
#include "engine/dynamics/event_record.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/dynamics/sleep_tracker.h"
#include "engine/dynamics/soft_rest.h"
#include "engine/dynamics/step_planner.h"
#include "engine/dynamics/step_stats.h"

namespace rugosim {

// The first accepted state in which two boundaries cross (StepStats::crossings > 0): when and
// where, for the warning of the commands and stats.json.
struct CrossingRecord {
  double time = 0.0;       // s, world time of the state
  std::size_t body_a = 0;  // the crossing pair first in the state's order (body_a < body_b)
  std::size_t body_b = 0;
  double depth = 0.0;  // m, sampled_overlap_depth of the pair (overlap_depth.h)
};

struct WorldSettings {
  Vec2 gravity = Vec2(0.0, -9.81);  // m/s²
  // k in μ = k·max(0, λ − λ_min), 1/m: 100/m gives μ = 0.1 for λ − λ_min = 1 mm, the scale of
  // the rugosities of the paper's examples in metres.
  double friction_gain = 100.0;
  // s: the longest internal step near a contact that closes (or opens) fast. 1 ms keeps a 1 m
  // fall at 4.4 m/s to 4.4 mm per step, so a pile is checked often enough for contacts to be
  // found near where they begin.
  double max_step = 1e-3;
  // A step in which every pair that can come within its bands moves, relative to each other,
  // at most kRestBandShare of its narrowest bands may last up to this many max_steps (a rest
  // step): resting and slowly rolling bodies are looked at less often than impacts. 1 keeps
  // every step near contact at max_step.
  int rest_stride = 16;
  // Slow contacts get their impulses at the start of each step, on the mid-step velocities
  // (mid_step_rest.h), and micro-collisions answer only faster approaches. An island whose
  // step crosses goes on without them for that step (World::step; §8.4 of
  // docs/research/resting-contact.md).
  bool mid_step_rest = true;
  // Share of its band a contact resting at mid-step reaches into it (mid_step_rest.h), in
  // (0, 1).
  double rest_depth = MidStepRestSettings{}.rest_depth;
  // Contact rules that do not depend on the step, so that trajectories converge as it shrinks
  // (docs/accuracy/convergence.md; issue 17). Off, the paper's rules as the World applied them
  // before, each of which the step enters:
  //   - a pair arriving within its bands faster than impact_speed (contact_plan.h) gets its
  //     collision where it arrived, located by bisection down to min_step as a crossing is,
  //     not where the step's end finds it, somewhere in the band;
  //   - an approach counts as resolved by its speed, impact_speed, not by resolved_gap_fraction
  //     of its gap per max_step;
  //   - a contact deeper than the rest depth is lifted back towards it at mid-step at a rate set
  //     by its band (mid_step_rest.h), not left where it is for the hop of a later step.
  bool converging_contacts = false;
  // Gauss-Seidel sweeps of a mid-step solve at most. A pile's solve often runs out of them
  // (counted in StepStats::rest_unconverged): what is left is answered by micro-collisions.
  int rest_sweeps = 64;
  // Substeps of the soft resting solve (soft_rest.h) that then replaces the hard mid-step solve,
  // and the slow approaches of its pairs stop without a hop; 0 keeps the hard solve. Without
  // mid_step_rest neither solve runs. A pile rests within a fifth of a band under it, so its
  // bodies are judged by the sleep test's stricter soft windows (SleepSettings::soft_bands); a
  // rest step it leaves too fast is halved (World::rest_for_step).
  int soft_rest_substeps = 8;
  double soft_rest_hertz = 60.0;  // Hz, its contact spring (SoftRestSettings::hertz)
  // The soft solve takes only the islands of at least this many moving bodies linked by
  // contacts whose bands are wide enough for its springs (soft_rest_movers); the others keep the
  // mid-step solve, whose rest is exact where it converges (a lone body on a slope does not
  // creep at all).
  int soft_rest_island = 2;
  // s: bisection stops below this step. 1e-9 s at 10 m/s is 10 nm, below the minimum band
  // (1e-6 of a 1 m body), so a contact is normally caught before the bound is reached.
  double min_step = 1e-9;
  // Bisections per step: 2^-60 of max_step is far below min_step, so min_step binds first.
  int max_bisections = 60;
  // Passes of contact resolution per accepted state.
  int max_resolution_passes = 64;
  // A contact is resolved when it would close at most this fraction of its gap within a step
  // (contact_resolution.h, "Resolved").
  double resolved_gap_fraction = 1e-3;
  NarrowPhaseSettings narrow_phase;  // the segment-pair search (segment_distance.h)
  bool record_events = true;         // keep a ContactEvent per impulse (events())
  SleepSettings sleep;
  // Threads for collision detection, the caller's included. Never changes a result: states,
  // events and stats are the same, bit for bit, for any count (collision_pipeline.h).
  int threads = 1;
};

// Where the World's time went (wall-clock seconds, summed since construction): for profiles and
// benchmarks, never for results (it differs from run to run).
struct StepProfile {
  double detection = 0.0;   // s, broad and narrow phase of every trial state
  double resolution = 0.0;  // s, impulses
  double stepping = 0.0;    // s, everything else: step lengths, free flight, islands, sleeping
};

class World {
 public:
  // After this many min-step fallbacks in a row, a crossing state is accepted (see above).
  static constexpr int kMaxConsecutiveFallbacks = 8;
  // Back-offs of one step at most before its backed-off islands hold still (see above).
  static constexpr int kMaxBackOffsPerStep = 32;
  // How far below min_step a back-off that has found no crossing-free trial yet may halve: 2⁻¹⁰
  // of it (for a gap that closes faster than the band is thick over min_step).
  static constexpr double kFinestStepShare = 1.0 / 1024.0;
  static constexpr int kMaxThreads = 256;
  // The share of a pair's narrowest bands (CollisionShape::least_band of each) it may close in
  // a rest step: half, so that a contact a rest step brings is found at most half as deep in its
  // band as a fall of max_step at v = band / max_step would bring it (3 mm at 1 ms is 3 m/s).
  static constexpr double kRestBandShare = 0.5;
  static constexpr int kMaxRestStride = 1024;

  // Throws std::invalid_argument on non-finite gravity, a negative friction gain, steps that
  // are not 0 < min_step <= max_step, non-positive loop bounds, narrow-phase settings out of
  // range (relative accuracy in (0, 1), positive counts) or threads outside [1, kMaxThreads].
  explicit World(WorldSettings settings = {});

  // Adds a body and returns its index (events and manifolds name bodies by it). The name is
  // for the caller's telemetry; the World does not require it to be unique.
  std::size_t add_body(RigidBody body, std::string name = {});

  std::size_t body_count() const { return bodies_.size(); }
  const RigidBody& body(std::size_t i) const { return bodies_[i]; }
  // Direct access, e.g. to set a state between calls to advance_to. A sleeping body given a
  // new state must be woken (wake) or it stays where it was put and does not move.
  RigidBody& body(std::size_t i) { return bodies_[i]; }
  bool asleep(std::size_t i) const { return sleep_.asleep(i); }
  // Wakes body i and the rest of its sleeping island; no-op when it is awake.
  void wake(std::size_t i) { sleep_.wake(bodies_, i, time_); }
  const std::string& name(std::size_t i) const { return names_[i]; }
  const WorldSettings& settings() const { return settings_; }

  double time() const { return time_; }  // s

  // Advances to time t (s) by internal steps; nothing happens when t <= time(). Returns early,
  // after the step in hand and short of t, when the stop flag is set (see set_stop_flag).
  void advance_to(double t);

  // A flag (e.g. set by a SIGINT handler) that advance_to polls before every step, so that a
  // run that crawls through many short steps still stops within one step; the World is left
  // in the accepted state of its last step. Null: never stop. Not a setting of the
  // simulation: it never changes a step that is taken.
  void set_stop_flag(const std::atomic<bool>* flag) { stop_ = flag; }
  bool stop_requested() const { return stop_ != nullptr && stop_->load(std::memory_order_relaxed); }

  const StepStats& stats() const { return stats_; }
  // The first accepted crossing state, if any: none unless stats().crossings > 0.
  const std::optional<CrossingRecord>& first_crossing() const { return first_crossing_; }
  const StepProfile& profile() const { return profile_; }
  // Every impulse since construction or the last clear_events(), in the order applied.
  const std::vector<ContactEvent>& events() const { return events_; }
  void clear_events() { events_.clear(); }
  // The crossings and contacts of the last accepted state (positions do not change while
  // impulses are applied, so these still describe the current state).
  const std::vector<ContactManifold>& manifolds() const { return manifolds_; }
  // soft_rest_substeps: the impulses the next rest step starts from (soft_rest.h).
  const SoftRestMemory& soft_rest_memory() const { return soft_memory_; }

  // Checkpoints (world_state.cpp): everything that steers the steps after this moment, exactly
  // (the bodies' states, time, the last state's manifolds and near pairs, the sleep records,
  // the statistics, the first crossing and the soft-rest impulses), as bytes. Events are not
  // included (the commands clear them every frame). restore_state takes a record saved by a World
  // built from the same scene and settings; it throws ByteStreamError for one that is malformed or
  // holds another number of bodies, leaving this World unchanged. Continuing after a restore gives,
  // bit for bit, what the World that saved it would have given.
  std::string save_state() const;
  void restore_state(std::string_view record);

 private:
  // Makes `members` (sorted body indices) the bodies that move in the current (sub-)step.
  void set_members(std::vector<std::size_t> members);
  // Saves the members' states as the start of a (sub-)step.
  void save_start();
  // Places every member at dt (s) of free flight from its start state.
  void place_at(double dt);
  // Runs detection on the current placement, every non-member held still; result in
  // detected_ and detected_pairs_.
  void detect();
  void detect_initial_contacts();  // manifolds_ and near_pairs_ of the state as it is
  // Adds to detected_ a crossing for every near pair without contact where one body lies wholly
  // inside the other (containment.h): nothing the boundaries show, yet no state to accept.
  void detect_containment();
  // Whether the last state had a near pair (boxes with bands overlapping) with an awake mover.
  bool near_anything() const;
  // The next step's length, at most `remaining` (s): all of it while nothing can meet, else
  // max_step cut so that nothing can tunnel (step_planner.h; never below min_step).
  double next_step(double remaining);
  // One step of h (s) for every awake movable body (islands that cross back off alone); returns
  // the step taken: h, or less when a soft rest asked for less (rest_for_step).
  double step(double h);
  // Marks as crossing (crossing_root, per island root) every island of the trial with a body
  // that a backing-off body could reach anywhere between its start and its trial place, while
  // that island would be held at its trial place: a backed-off island must never meet a body
  // accepted at h (islands apart at the step's end can be close in between).
  void join_islands_within_reach(DisjointSets& islands, std::vector<std::uint8_t>& crossing_root,
                                 double h) const;
  // Advances the members, whose full move to h (s after time_) was found to cross, by
  // back-off and further sub-steps until they reach h.
  // trial_crosses: the move to h was tried from the members' state now and crossed.
  void advance_crossing_members(double h, bool trial_crosses);
  // Bisects the members' move of dt_full (s) whose end crosses; returns the accepted dt (0 after
  // a min-step fallback), leaves the members there and the manifolds in accepted_.
  double back_off(double dt_full);
  // Impacts located in time (WorldSettings::converging_contacts; world_impacts.cpp). Remembers
  // the pairs within their bands at the start of a (sub-)step, and forgets the pairs located
  // since the step began when `new_step`.
  void mark_start_contacts(const std::vector<ContactManifold>& start, bool new_step);
  // Whether a trial state must be backed off: a pair crosses, or (converging_contacts) a pair
  // outside its bands at the (sub-)step's start and not yet located in this step arrives within
  // them faster than impact_speed. `arriving` (if given) receives the latter, sorted.
  bool overshoots(const std::vector<ContactManifold>& manifolds,
                  std::vector<std::pair<std::size_t, std::size_t>>* arriving = nullptr) const;
  // Whether a contact of the pair approaches faster than impact_speed (contact_plan.h).
  bool arrives_fast(const ContactManifold& m) const;
  // The state accepted now holds these arrivals where they happened; none is located again in
  // this step.
  void locate(const std::vector<std::pair<std::size_t, std::size_t>>& arriving);
  // When the members' move of dt_full (s) crosses nothing but brings pairs within their bands
  // too fast: the earliest of those pairs' arrival times, each bisected on its own two bodies
  // (a pair's narrow phase, not the island's detection), then confirmed by one detection of
  // the island there. Returns the accepted dt with the members there and the manifolds in
  // accepted_, or nothing when the confirmation finds more (a crossing, another arrival); then
  // detected_ holds the members' state at `*hi` (s), which still overshoots, for back_off to
  // bisect below.
  std::optional<double> locate_arrivals(double dt_full, double* hi);
  // At a min-step fallback: moves the touching pairs among `pairs` (sorted) apart by twice the
  // touching depth, unless that crosses another pair. Leaves the manifolds of the state it
  // holds in detected_.
  void push_touching_apart(const std::vector<std::pair<std::size_t, std::size_t>>& pairs);
  // Before the members move by h (s) from the state whose manifolds are given: their slow
  // contacts' impulses at mid-step, when settings_.mid_step_rest (mid_step_rest.h).
  void rest_at_mid_step(const std::vector<ContactManifold>& manifolds, double h);
  // Rests them so, saves the members' start and places them at h; after a soft rest each body it
  // touched takes the substeps' last velocities (soft_rest.h).
  void rest_and_place(const std::vector<ContactManifold>& manifolds, double h);
  // rest_at_mid_step from manifolds_ for a step of h (s), and the step to take: h, or for a rest
  // step (over max_step) after which a softly rested body moves further than a rest step
  // allows, the first halving of it (max_step at least) that the solve keeps gentle, solved
  // again from the members' state before (counted in soft_rest_retries).
  double rest_for_step(double h);
  // The second half of rest_and_place: saves the start and places the members at h (s).
  void place_rested(double h);
  // Impulses for the manifolds of an accepted state at `time` (s), and the step statistics.
  void resolve(const std::vector<ContactManifold>& manifolds, double time);
  // Sets first_crossing_ from the first intersecting pair of `manifolds` (an accepted state).
  void record_first_crossing(const std::vector<ContactManifold>& manifolds, double time);

  WorldSettings settings_;
  std::vector<RigidBody> bodies_;
  std::vector<std::string> names_;
  std::vector<std::size_t> members_;  // bodies moving in the current (sub-)step
  std::vector<std::uint8_t> moving_;  // per body: 1 when a member
  std::vector<BodyState> start_;      // per body: a member's state at the sub-step's start
  std::vector<PlacedShape> placed_;
  std::vector<std::optional<ContainmentSamples>> containment_;  // per body, made when first needed
  CollisionPipeline pipeline_;
  StepPlanner planner_;
  ContactResolver resolver_;
  std::vector<std::uint8_t> awake_;  // per body: 1 when neither fixed nor asleep (next_step)
  OwnedThreadPool pool_;
  std::vector<ContactManifold> detected_;   // copy of the latest detection
  std::vector<BodyPair> detected_pairs_;    // its broad-phase pairs
  std::vector<ContactManifold> accepted_;   // of the state back_off accepted
  std::vector<BodyPair> accepted_pairs_;    // its broad-phase pairs
  std::vector<ContactManifold> manifolds_;  // of the state at the end of the last step
  std::vector<BodyPair> near_pairs_;        // its broad-phase pairs
  // Whether manifolds_ describe the bodies as they are: false until the first step has looked
  // at the initial state, and again after add_body.
  bool contacts_known_ = false;
  std::vector<ContactEvent> events_;
  SleepTracker sleep_;
  StepStats stats_;
  std::optional<CrossingRecord> first_crossing_;
  const std::atomic<bool>* stop_ = nullptr;
  StepProfile profile_;
  double time_ = 0.0;  // s
  int consecutive_fallbacks_ = 0;
  double rest_step_ = 0.0;          // s, ResolutionSettings::rest_step of the step in hand
  std::vector<RestedPair> rested_;  // its ResolutionSettings::rested
  // soft_rest_substeps: the impulses carried from step to step (state, checkpointed), and the
  // velocities the bodies of the step in hand take once placed at its end.
  SoftRestMemory soft_memory_;
  std::vector<EndVelocity> end_velocities_;
  // Mid-step rest: each member's state before the step's impulses, and whether the crossing
  // members of this step went on without them (World::step).
  std::vector<BodyState> before_rest_;
  bool rest_withdrawn_ = false;
  // converging_contacts: the pairs within their bands at the (sub-)step's start, and those
  // located in this step (each at most once a step, so that an arrival no impulse turns back
  // cannot make the step crawl); both sorted.
  std::vector<std::pair<std::size_t, std::size_t>> start_contacts_;
  std::vector<std::pair<std::size_t, std::size_t>> located_;
  BodyPairCollider locator_;  // locate_arrivals' narrow phase for one pair at a time
};

}  // namespace rugosim
