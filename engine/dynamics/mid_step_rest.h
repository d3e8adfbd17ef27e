// Resting contact at mid-step (docs/research/resting-contact.md, §5 phase S and §8.3): before
// a step of length h moves the bodies, the slow contacts of the state at its start get
// impulses (slow_contacts.h) computed on the bodies' velocities at the step's middle,
// u + g·h/2 for a body that moves.
//
// Why the middle: free flight under constant gravity moves a body over h by exactly its
// mid-step velocity times h (free_flight.h; the spin is constant). So when S leaves every slow
// contact at mid-step approaching no faster than its allowance, and its slip stopped within the
// Coulomb cone, the contact closes over the step by at most the allowance times h, and does not
// slide: a body resting on a slope stays where it is, whatever h is. Micro-collisions alone
// look at a contact only after a whole step of free fall, so a body on a slope slides
// ½·g·sinθ·h² per step and creeps at ½·g·sinθ·h, growing with the step (§8.2).
//
// A contact of band λ (as contact_resolution.h defines it) rests at `rest_depth`·λ from the
// far edge of its band: its allowance is max(0, d − (1 − rest_depth)·λ)/h for a gap d, so a
// contact still outside that depth may close to it within the step and no further.
//
// A fixed or sleeping body is immovable here (inverse mass 0): a sleeping island touched by an
// awake body is woken at the step's end by the usual rule (sleep_tracker.h). Contacts of a
// crossing pair are skipped: the back-off answers them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/contact.h"
#include "engine/core/types.h"
#include "engine/dynamics/contact_rows.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct MidStepRestSettings {
  Vec2 gravity = Vec2(0.0, -9.81);  // m/s²
  double friction_gain = 100.0;     // k, 1/m
  // Share of its band a resting contact reaches into it (0: rests at the band's far edge, 1:
  // at touching). A fifth: near the far edge, where micro-collisions keep bodies hovering too;
  // deeper, more leaf pairs lie within the bands and detection costs more (§8.3: the 200-body
  // pile 1.75 s at a fifth, 2.2 s at a half).
  double rest_depth = 0.2;
  SweepSettings sweeps;
  // WorldSettings::converging_contacts: a contact deeper than the rest depth is lifted back towards
  // it at (d_r − d)/max(√(2λ/|g|), h) (its allowance negative): in the time a fall through its
  // band takes, not in one step, so that how fast it rises does not depend on the step. (A band
  // that grows under a sliding or rolling body makes its contacts deep without any approach.)
  bool lift = false;
};

// A body pair whose contacts got mid-step impulses, and the fastest approach any of them was
// allowed (m/s): until the next step's impulses, an approach up to that plus what gravity adds
// in the step is theirs to answer (contact_resolution.h, "Resolved").
struct RestedPair {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  double allowance = 0.0;  // m/s
  // Rested by the soft solve (soft_rest.h): its slow approaches stop without a hop
  // (ContactStatics::inelastic_below).
  bool soft = false;
};

struct MidStepRestCounts {
  std::uint64_t contacts = 0;  // slow-contact rows solved
  std::uint64_t pushed = 0;    // rows that got a normal impulse
  std::uint64_t sweeps = 0;
  bool converged = true;           // false when the sweeps ran out (counted, not fatal: §8.1)
  std::vector<RestedPair> rested;  // in the manifolds' (body_a, body_b) order
};

// With mid-step rest, the share of its band a contact must reach into before micro-collisions
// answer its slow approach (contact_plan.h): halfway from the rest depth to touching, so that a
// contact resting at the rest depth, give or take what one step of gravity and rounding moves
// it, is left to the mid-step impulses.
inline double deep_share(double rest_depth) {
  return 0.5 * (1.0 + rest_depth);
}

// The sweeps of a mid-step solve, for a World of the given gravity (m/s²) and max_step (s),
// `max_sweeps` at most (the `rest_sweeps` accuracy knob): converged when no contact velocity
// changes by more than 1e-6 of |g|·max_step in a sweep (a looser 1e-3 let the incline creep at
// 3e-7 m/s: docs/research/resting-contact.md §8.3).
SweepSettings rest_sweep_settings(const Vec2& gravity, double max_step, int max_sweeps);

// The entry of `rested` (sorted by pair) for the pair (a, b), or null.
const RestedPair* find_rested(std::span<const RestedPair> rested, std::size_t a, std::size_t b);

// Applies the mid-step impulses of the contacts of `manifolds` (the state now) to the
// velocities of `bodies`; `moves[i]` is 1 for a body that moves in the step of h (s). The solve
// starts cold: warm starts by contact identity were tried and, with sub-steps a million times
// shorter than a step, carried impulses that threw piles apart (docs/research/resting-contact.md
// §8.3).
MidStepRestCounts rest_at_mid_step(std::span<RigidBody> bodies, std::span<const std::uint8_t> moves,
                                   std::span<const ContactManifold> manifolds, double h,
                                   const MidStepRestSettings& settings);

}  // namespace rugosim
