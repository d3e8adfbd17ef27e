// The impulses of slow approaches, for resting contact (docs/research/resting-contact.md, §5
// phase S; with contact_forces.h, the resting-contact model of issues 14 and 17, not yet used
// by World).
//
// Micro-collisions (paper §4.3) answer a contact that approaches slowly inside its band with a
// little bounce that lifts it back out, one contact at a time, in passes. Here all such contacts
// of a state are answered together, inelastically: impulses that leave every contact
// approaching no faster than its `allowance` (the speed at which one longest step would close
// the gap down to where the contact should rest), with friction stopping the slip within the
// Coulomb cone. A one-contact-at-a-time scheme needs many passes for a body resting on two
// others, and can run out of them; solved simultaneously (projected Gauss-Seidel on the rows of
// contact_rows.h: Δu_n ≥ −allowance − u_n, Δu_t = −u_t) it converges to the inelastic answer.
// Collisions (faster approaches, with restitution) stay with collision_impulse.h.
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/contact_rows.h"

namespace rugosim {

// One contact. `impulse` is read as the warm start and written with the solution.
struct SlowContact {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  Vec2 point = Vec2::Zero();    // m, world
  Vec2 normal = Vec2::UnitY();  // unit, from B towards A
  double allowance = 0.0;       // m/s ≥ 0, the approach the contact may keep
  double friction = 0.0;        // μ ≥ 0
  Vec2 impulse = Vec2::Zero();  // N·s, (normal, tangent) on A; B receives the opposite
};

struct SlowContactResult {
  std::vector<VelocityChange> change;  // per body: what the impulses did to its velocity
  int sweeps = 0;
  double residual = 0.0;  // m/s, the largest change of a contact velocity in the last sweep
  bool converged = false;
  std::size_t pushed = 0;  // contacts that got a normal impulse
};

// The impulses for contacts between `bodies` (their velocities now). A contact separating or
// approaching within its allowance gets none unless another contact's impulse makes it
// approach. The scale of the tolerance is `speed_floor` (m/s; |g|·max_step for a World),
// or the fastest excess approach when that is more.
SlowContactResult solve_slow_contacts(std::span<const SolverBody> bodies,
                                      std::span<SlowContact> contacts,
                                      const SweepSettings& settings);

}  // namespace rugosim
