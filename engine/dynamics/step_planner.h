// How long the World's next step may be (DESIGN.md, "Dynamics"; world.h, steps 0 and 0′).
//
// Long while nothing can meet: free flight is exact, so a step in which no two bodies can come
// within their bands needs no detection in between and may run to the next frame. Whether
// they can is decided on the broad-phase boxes (bands included) grown by how far each body can
// move in the step, in a frame that falls with gravity and drifts with the movers' mean velocity
// v̄: there a mover's box sweeps at most (|v − v̄| + |ω|·reach)·h and a fixed or sleeping body's
// at most |v̄|·h + ½|g|·h² (triangle inequality: every pair's relative motion is within the sum
// of its two sweeps). Bodies falling together side by side, however fast, then do not hold one
// another to short steps.
//
// Short enough not to tunnel: two bodies whose boxes could meet within the step move, relative
// to each other, at most half the thinner one's thickness (RigidBody::thickness), so that the
// crossing check at the step's end sees any overlap before a body can get through. Relative
// motion of two movers is bounded by |v_i − v_j| + |ω_i|·r_i + |ω_j|·r_j (gravity moves both
// alike); of a mover and a fixed or sleeping body by the mover's |v| + |ω|·r and ½|g|·h². The pairs
// are found by the same broad phase over boxes grown by each body's own reach, so the cost is
// that of a sweep, not of all pairs.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/broad_phase.h"
#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

class StepPlanner {
 public:
  // Whether no two bodies, at least one of them moving (moves[i] != 0), can come within their
  // bands during the next h (s) of free flight under `gravity` (m/s²).
  bool nothing_can_meet(std::span<const RigidBody> bodies, std::span<const std::uint8_t> moves,
                        const Vec2& gravity, double h);

  // The longest step, at most h (s) and at least min_step (s), in which no pair of bodies can
  // tunnel (see above).
  double tunnel_free(std::span<const RigidBody> bodies, std::span<const std::uint8_t> moves,
                     const Vec2& gravity, double h, double min_step);

  // The longest step, at most h (s), in which every pair that can come within its bands moves,
  // relative to each other, at most band_share of the narrowest band the two can meet with
  // (CollisionShape::least_band of each): a step in which contacts are found as shallow in their
  // bands as that share. 0 when some pair is already closing that far at once.
  double gentle_step(std::span<const RigidBody> bodies, std::span<const std::uint8_t> moves,
                     const Vec2& gravity, double h, double band_share);

 private:
  // The longest step, at most h, in which every pair that can meet moves relative to each other
  // at most pair_limit(i, j) (m).
  template <typename PairLimit>
  double longest_step(std::span<const RigidBody> bodies, std::span<const std::uint8_t> moves,
                      double g, double h, const PairLimit& pair_limit);

  SweepAndPrune broad_phase_;
  std::vector<BroadPhaseProxy> proxies_;
  std::vector<Aabb> boxes_;
};

}  // namespace rugosim
