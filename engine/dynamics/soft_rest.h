// Soft resting contact (the `soft_rest` accuracy knob; docs/research/resting-contact.md §8.16):
// the mid-step solve of mid_step_rest.h replaced by Box2D v3's soft step, run over the rest
// step in substeps, for piles that must come to rest and sleep.
//
// Why: the hard mid-step solve asks every slow contact to stop at once. On a pile its
// Gauss-Seidel sweeps run out (StepStats::rest_unconverged) and what is left goes to
// micro-collisions, so the pile keeps compacting by a few cm/s and never sleeps. Box2D v3's
// answer (Catto, "Solver2D", 2024) is a contact that is a stiff damped spring past its rest
// depth and a speculative constraint before it, solved a few times per step with the
// impulses of the last step applied first (warm starting). Those three together converge where
// one hard solve per step cannot: the 200-body pile comes to rest within half a band.
//
// One rest step of length h runs `substeps` substeps of hs = h/n. Each substep:
//   1. gravity for hs;
//   2. warm start: the accumulated impulses of every contact row applied again;
//   3. one biased sweep: a row deeper than its rest depth is soft (spring at `hertz`, damping
//      ratio `damping_ratio`, capped at a quarter of the substep's rate); a row short of it may
//      close its gap within the substep and no further;
//   4. displacement and turn integrated from the velocities (the bodies themselves are not
//      moved: rows see the gap through the displacements);
//   5. one relax sweep with no bias, so that the pushing does not stay as velocity.
// Afterwards the flight over h must land where the substeps did: a body gets the start velocity
// D/h − g·h/2 and spin Θ/h (free flight is exact, free_flight.h), and once placed at h the
// substeps' last velocities (EndVelocity).
//
// The impulses are remembered between steps (SoftRestMemory), keyed by body pair and segment
// pair, and carried over scaled by the ratio of the substeps. They are part of the World's
// state: checkpoints save them and the state hash covers them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/contact.h"
#include "engine/core/byte_stream.h"
#include "engine/core/types.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct SoftRestSettings {
  Vec2 gravity = Vec2(0.0, -9.81);  // m/s²
  double friction_gain = 100.0;     // k, 1/m
  double rest_depth = MidStepRestSettings{}.rest_depth;
  int substeps = 8;  // Box2D v3 takes 4 per 60 Hz step; a rest step is up to 16 ms here
  // Hz: the contact spring's frequency (Box2D's contact hertz is 30). 60 Hz left the 200-body
  // pile still two seconds sooner than 30 Hz (§8.16). A row that carries more than its spring
  // holds within its band is made stiffer for its load (rest_softly, §8.20); a stiffer spring for
  // every row left rocking bodies awake (one of the small piles at 120, 140 or 240 Hz).
  double hertz = 60.0;
  double damping_ratio = 10.0;  // Box2D v3's contact damping ratio: overdamped, no bounce back
  // No cap on the push apart (Box2D caps it at 3 m/s): a contact is never deeper than its band,
  // so the spring pushes at most bias_rate·λ, about 0.3·hertz·λ (0.07 m/s for a 4 mm band at
  // 60 Hz). Caps of 0.1, 0.3 and 1 m/s gave the 200-body pile the same trajectory, bit for bit.
};

// What one contact row held at the end of a rest step: its accumulated normal and tangent
// impulses per substep (N·s).
struct SoftRestImpulse {
  std::size_t body_a = 0;
  std::size_t body_b = 0;
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  double normal = 0.0;
  double tangent = 0.0;

  friend bool operator==(const SoftRestImpulse&, const SoftRestImpulse&) = default;
};

// The warm starts of the next rest step: the impulses of the last step that was at least half
// as long as the one before it, sorted by (body_a, body_b, segment_a, segment_b), one per key.
class SoftRestMemory {
 public:
  double substep() const { return substep_; }  // s; 0 when empty
  std::span<const SoftRestImpulse> impulses() const { return impulses_; }
  // The impulse remembered for a row, or nullptr.
  const SoftRestImpulse* find(std::size_t body_a, std::size_t body_b, std::size_t segment_a,
                              std::size_t segment_b) const;
  // Replaces the memory; of two impulses with the same key the later one is kept.
  void replace(double substep, std::vector<SoftRestImpulse> impulses);
  void clear();

  // Checkpoints (World::save_state), exactly. restore() checks every body and segment index
  // against `bodies` and throws ByteStreamError for one past the end.
  void save(ByteWriter& out) const;
  void restore(ByteReader& in, std::span<const RigidBody> bodies);

  friend bool operator==(const SoftRestMemory&, const SoftRestMemory&) = default;

 private:
  double substep_ = 0.0;
  std::vector<SoftRestImpulse> impulses_;
};

// The velocities a body must have once the flight over the rest step has placed it.
struct EndVelocity {
  std::size_t body = 0;
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;
};

struct SoftRestCounts {
  std::uint64_t contacts = 0;      // contact rows solved
  std::vector<RestedPair> rested;  // every contact pair with a moving body, allowance 0
  std::vector<EndVelocity> end;    // for World to set after the flight (see above)
};

// Per body: 1 when it moves (`moves`) and belongs to an island of at least `min_island` moving
// bodies linked by pairs in contact (fixed and sleeping bodies link nothing) whose every
// contact, those with fixed bodies included, has a band λ_a + λ_b of at least `min_band` (m):
// the bodies the soft solve takes (World::rest_at_mid_step).
std::vector<std::uint8_t> soft_rest_movers(std::span<const std::uint8_t> moves,
                                           std::span<const ContactManifold> manifolds,
                                           int min_island, double min_band = 0.0);

// m: the narrowest band the soft solve takes, 10·g/ω² (ω = 2π·hertz; 0.69 mm at 60 Hz). Under
// a load its spring sits g/ω² (0.07 mm) deeper than its rest depth; a band ten times that holds
// the sag, the damping's overshoot and the hops of the pairs around it. A narrower one (bodies
// of σ = 0, whose band is the minimum band) rests by the mid-step solve, which needs no room.
// §8.18 of docs/research/resting-contact.md.
double soft_rest_min_band(const Vec2& gravity, double hertz);

// One rest step of length h (s) for the contacts of `manifolds` (pairs in contact only) between
// bodies of which at least one moves (`moves`, per body). Sets the start velocities of the
// bodies it touched, updates `memory` (a step shorter than half the remembered one, such as a
// frame's remainder or a back-off, only uses it: its impulses would be scaled up next time) and
// returns the velocities to set after the flight.
SoftRestCounts rest_softly(std::span<RigidBody> bodies, std::span<const std::uint8_t> moves,
                           std::span<const ContactManifold> manifolds, double h,
                           const SoftRestSettings& settings, SoftRestMemory& memory);

}  // namespace rugosim
