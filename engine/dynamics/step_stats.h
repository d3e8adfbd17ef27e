// Counters of the World's time stepping, for stats.json (INTERFACE.md) and for tests that must
// see every fallback: a loop that hit its bound shows up here instead of silently.
#pragma once

#include <cstdint>

namespace rugosim {

struct StepStats {
  std::uint64_t steps = 0;  // accepted states (steps, and sub-steps of backed-off islands)
  // Trial states tried while backing off to first contact, an arriving pair's own placements
  // (World::locate_arrivals) included.
  std::uint64_t bisections = 0;
  std::uint64_t collisions = 0;  // impulses from plain collisions (events of kind collision)
  std::uint64_t contacts = 0;    // resting-contact micro-collisions (events of kind contact)
  // Every time a bounded loop ran out and a documented fallback was used (the sum of the
  // min-step, pass and stalled-step kinds below).
  std::uint64_t fallbacks = 0;
  std::uint64_t min_step_fallbacks = 0;  // back-off reached the minimum step without progress
  std::uint64_t pass_fallbacks = 0;      // resolution passes ran out with contacts approaching
  std::uint64_t rigid_clusters = 0;      // clusters then resolved as rigid bodies (pass_fallbacks)
  // Accepted states left with a contact approaching even after the rigid clusters.
  std::uint64_t unresolved_states = 0;
  std::uint64_t crossing_fallbacks = 0;  // repeated min-step fallbacks: a crossing was accepted
  // Steps whose back-offs ran out (World::kMaxBackOffsPerStep) without reaching the step's end:
  // the backed-off islands held still for the rest of the step.
  std::uint64_t stalled_steps = 0;
  double stalled_time = 0.0;  // s: those rests of steps, summed (an island's lost time)
  // Accepted states in which two boundaries cross: 0 is the goal, and only crossing_fallbacks
  // can make it grow.
  std::uint64_t crossings = 0;
  std::uint64_t passes = 0;         // contact-resolution passes over all the contacts of a state
  std::uint64_t islands_slept = 0;  // islands of resting bodies put to sleep
  std::uint64_t islands_woken = 0;  // sleeping islands woken by a touch
  // Steps skipped because every movable body slept (the World jumped to the target time).
  std::uint64_t idle_jumps = 0;
  // Steps taken whole to the target time because no two bodies could meet in them.
  std::uint64_t free_steps = 0;
  // Steps near contact longer than max_step because every pair that could meet in them moved
  // gently (WorldSettings::rest_stride).
  std::uint64_t rest_steps = 0;
  // Mid-step resting contact (WorldSettings::mid_step_rest, mid_step_rest.h): contact rows
  // solved, summed over the (sub-)steps; their Gauss-Seidel sweeps; and the solves whose sweeps
  // ran out before converging (the impulses so far are kept: the next step starts from there).
  std::uint64_t rest_contacts = 0;
  std::uint64_t rest_sweeps = 0;
  std::uint64_t rest_unconverged = 0;
  // Steps whose crossing island went on without its mid-step impulses (World::step).
  std::uint64_t rest_withdrawn = 0;
  // Rest steps whose soft solve left a body moving faster than the step allows (World::step):
  // the step was halved and solved again.
  std::uint64_t soft_rest_retries = 0;
  // Awake movable bodies summed over the steps: the work a step's cost grows with (wall time
  // per body-step compares scenes of different sizes).
  std::uint64_t body_steps = 0;
  double sim_time = 0.0;  // s simulated
};

}  // namespace rugosim
