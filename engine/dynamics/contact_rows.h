// The projected Gauss-Seidel core shared by the resting-contact solves (docs/research/
// resting-contact.md §5): constant forces over a step (contact_forces.h) and the impulses of
// slow approaches (slow_contacts.h). Both ask the same of each contact: a change Δu of its
// relative velocity, made by an accumulated x = (x_n, x_t) with Δu = Kx (K: collision_impulse.h),
// such that
//   normal:  Δu_n ≥ normal_target,  x_n ≥ 0, one of them tight;
//   tangent: Δu_t = tangent_target, clamped to |x_t| ≤ μ·x_n (Coulomb).
// The callers differ only in what the targets are (an end-of-step gap, an approach speed) and
// what x means (φ = f·h or an impulse, both N·s).
//
// Rows are visited in their given order, friction before normal in each contact as Box2D 2.4.1
// does (its sequential impulses with accumulated clamping), so the result is bit-reproducible.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/types.h"

namespace rugosim {

// What the solves need of a body. A fixed body has inverse_mass = inverse_inertia = 0.
struct SolverBody {
  double inverse_mass = 0.0;      // 1/kg
  double inverse_inertia = 0.0;   // 1/(kg·m²)
  Vec2 position = Vec2::Zero();   // m, centre of mass
  Vec2 velocity = Vec2::Zero();   // m/s
  double angular_velocity = 0.0;  // rad/s
};

// One contact as the core sees it.
struct VelocityRow {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  Vec2 point = Vec2::Zero();    // m, world
  Vec2 normal = Vec2::UnitY();  // unit, from B towards A
  double friction = 0.0;        // μ ≥ 0
  double normal_target = 0.0;   // m/s, the least Δu_n
  double tangent_target = 0.0;  // m/s, the Δu_t wanted
  Vec2 impulse = Vec2::Zero();  // N·s, (normal, tangent) on A: the warm start in, the solution out
};

// A row for a contact at `point` (m, world) with `normal` between bodies[body_a] and
// bodies[body_b], its targets and impulse left at zero for the caller, and the contact's
// relative velocity now, u = u_A − u_B (m/s, collision_impulse.h).
struct StartedRow {
  VelocityRow row;
  Vec2 velocity = Vec2::Zero();
};
StartedRow start_row(std::span<const SolverBody> bodies, std::size_t body_a, std::size_t body_b,
                     const Vec2& point, const Vec2& normal, double friction);

// The velocity changes a solution makes, per body.
struct VelocityChange {
  Vec2 velocity = Vec2::Zero();   // m/s
  double angular_velocity = 0.0;  // rad/s
};

struct RowSolution {
  std::vector<VelocityChange> change;  // per body (zero for a fixed one)
  int sweeps = 0;                      // sweeps done
  double residual = 0.0;  // m/s, the largest change of a contact velocity in the last sweep
  bool converged = false;
};

// How the sweeps stop.
struct SweepSettings {
  int max_sweeps = 64;
  // Converged when no row changed its contact's relative velocity by more than `tolerance`
  // times the speed scale in a sweep: the largest normal_target of a row an impulse can move,
  // or `speed_floor` when that is more. Only the pushes a row asks for set the scale: a wide
  // gap's large negative target must not loosen the tolerance of the contacts that rest.
  double tolerance = 1e-9;
  // m/s, > 0 in practice (the World's |g|·max_step): at 0, a set of rows that asks for no push
  // converges only when a sweep changes nothing at all.
  double speed_floor = 0.0;
};

// Solves the rows. A warm start is first clamped into the cone (x_n ≥ 0, |x_t| ≤ μ x_n). A row
// that no impulse can move along its normal (K_nn = 0) is left at zero.
RowSolution solve_velocity_rows(std::span<const SolverBody> bodies, std::span<VelocityRow> rows,
                                const SweepSettings& settings);

}  // namespace rugosim
