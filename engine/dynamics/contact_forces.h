// Constant contact forces over a step, for resting contact (docs/research/resting-contact.md,
// §5 phase F; the first piece of the resting-contact model of issues 14 and 17, not yet used by
// World).
//
// Micro-collisions (paper §4.3) hold a resting body up by lifting it at every step: it hops
// inside its band, and the hops decide where steps land. Here the contacts of an island instead
// get the constant forces f_i that, applied over the whole coming step of length h together with
// gravity, leave every contact's gap at the step's end at or above zero and its tangential
// velocity at zero where friction can hold it (Coulomb: |f_t| ≤ μ f_n). A body at rest then ends
// the step with exactly zero velocity. Because rugosim integrates flight in closed form, a
// constant force is closed form too (driven_flight in free_flight.h).
//
// Unknowns are φ_i = f_i·h (N·s). A constant force changes the relative contact velocity at the
// step's end by Kφ and the contact's relative position by ½h·Kφ (K: collision_impulse.h), to
// first order in the bodies' turn during the step. With w the relative contact velocity now,
// a_g the relative acceleration gravity gives (g on each movable body), s the gap the step may
// close (m), and n, t the contact's normal and tangent:
//   normal row:  s + h·w_n + ½h²·a_g,n + ½h·(Kφ)_n ≥ 0,  φ_n ≥ 0, one of them tight
//                (the end gap is what the row constrains, so a thin band is never crossed by a
//                body that rests the whole step under gravity: ½gh² may be far wider than it);
//   tangent row: w_t + h·a_g,t + (Kφ)_t = 0 (stick), clamped to |φ_t| ≤ μ·φ_n (slip).
// Solved by projected Gauss-Seidel with accumulated clamping (contact_rows.h: Catto's sequential
// impulses on the rows above), warm-started from the forces of the last step, which converge to
// the simultaneous solution that a one-contact-at-a-time impulse scheme never reaches. The result
// is bit-reproducible.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/types.h"
#include "engine/dynamics/contact_rows.h"

namespace rugosim {

// What the solver needs of a body (the state at the start of the step). A fixed body has
// inverse_mass = inverse_inertia = 0 and feels no gravity.
using ForceBody = SolverBody;

// One contact row. `force` is read as the warm start and written with the solution.
struct ForceContact {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  Vec2 point = Vec2::Zero();    // m, world
  Vec2 normal = Vec2::UnitY();  // unit, from B towards A
  double gap = 0.0;             // m, how far the contact may close during the step (≥ 0 wanted)
  double friction = 0.0;        // μ ≥ 0
  Vec2 force = Vec2::Zero();    // N, (normal, tangent) components on A; B receives the opposite
};

struct ForceSettings {
  int max_sweeps = 64;
  // Converged when no row changed its contact's relative velocity by more than this share of
  // the step's velocity scale in a sweep: |g|·h, or the largest normal velocity change a row
  // asks for when that is more (a fast approach into a gap). The scale is that of the
  // velocity changes the forces make, not of the velocities: a fast slide needs no more
  // sweeps than a slow one.
  double tolerance = 1e-9;
};

struct ForceResult {
  std::vector<Vec2> acceleration;            // m/s² per body, gravity included (0 when fixed)
  std::vector<double> angular_acceleration;  // rad/s² per body
  int sweeps = 0;                            // sweeps done
  double residual = 0.0;  // m/s, the largest change of a contact velocity in the last sweep
  bool converged = false;
};

// The constant contact forces for a step of h > 0 (s) under `gravity` (m/s²). Contacts whose
// bodies are both fixed (or that no force can move along their normal) are left at zero force.
ForceResult solve_contact_forces(std::span<const ForceBody> bodies,
                                 std::span<ForceContact> contacts, const Vec2& gravity, double h,
                                 const ForceSettings& settings = {});

}  // namespace rugosim
