// Impulses for every contact of an accepted state (paper §4.3; DESIGN.md, "Dynamics").
//
// Material mixing: μ = max(μ_a(t_a), μ_b(t_b)) from rugosity (§4.2), ε = max(ε_a, ε_b) and
// ε_max = max(ε_max,a, ε_max,b). The max follows the paper's rule for μ (the livelier surface
// decides) and keeps ε <= ε_max, which each material already guarantees.
//
// Band of a contact: λ = max(λ_a(t_a) + λ_b(t_b), min_band_a + min_band_b), the same band the
// collision layer used to call the pair a contact; the penetration into it is
// δ = clamp(λ − distance, 0, λ).
//
// Resting contact by micro-collisions (§4.3). Let g_n be gravity's component pressing the
// contact shut: −g·n when only A moves, g·n when only B moves, |g·n| when both move (the upper
// body presses on the lower one). A contact is resting when g_n > 0, δ > 0 and it approaches
// slowly, −√(2 g_n λ) < v_n < 0: no faster than a fall through the whole band. It then gets a
// micro-collision: the impulse is computed as if the approach speed were
// v_n* = min(v_n, −√(2 g_n δ)) with restitution ε_c(δ) = (ε_max − ε)/λ²·δ² + ε, and applied to
// the real velocities, which then leave at v_n − (1 + ε_c)·v_n* >= 0. Deeper in the band the
// push is stronger, so a body hovers in its band instead of sinking through it. With zero
// gravity, or gravity not pressing (g_n <= 0), every approaching contact is a plain collision,
// and a contact with v_n >= 0 gets nothing.
//
// Resolved: a contact needs an impulse only when it approaches faster than
// resolved_gap_fraction × distance / max_step, i.e. when it would close more than that
// fraction (0.1%) of the gap left between the curves within a step. Slower approaches are
// rounding residues of earlier impulses (or of a rigid cluster) that the next step catches
// long before they matter, and chasing them would spend every pass for nothing; a contact
// with no gap left counts any approach.
//
// Several contacts: each pass sorts the approaching contacts by their (perturbed) approach
// speed, most negative first, and recomputes each one's velocities just before its impulse;
// passes repeat until one applies nothing. Passes are bounded; when they run out with a
// contact still approaching (counted as a fallback), the clusters holding such contacts are
// resolved as rigid bodies (rigid_cluster.h). Whatever still approaches after that is left to
// the next step's back-off.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/collision/contact.h"
#include "engine/core/types.h"
#include "engine/dynamics/event_record.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct ResolutionSettings {
  Vec2 gravity = Vec2(0.0, -9.81);      // m/s²
  double friction_gain = 100.0;         // k, 1/m
  int max_passes = 64;                  // bound on passes over all contacts
  double max_step = 1e-3;               // s, the World's longest step
  double resolved_gap_fraction = 1e-3;  // see "Resolved" above
  // s: the step just taken when slow contacts rest at mid-step (mid_step_rest.h), else 0. An
  // approach slower than g_n times it is what the step's own gravity brought since the
  // mid-step impulses, which the next step's mid-step impulses answer: a micro-collision here
  // would count friction twice.
  double rest_step = 0.0;
  // The pairs that got mid-step impulses in that step, sorted by (body_a, body_b): an approach
  // up to their allowance plus g_n·rest_step is left to the next step's impulses too.
  std::span<const RestedPair> rested;
  // Share of its band a contact rests in at mid-step (mid_step_rest.h): a contact deeper than
  // that is not left to the mid-step impulses, whose allowance only stops its approach; it gets
  // its micro-collision, which lifts it back.
  double rest_depth = MidStepRestSettings{}.rest_depth;
  // Sweeps of a mid-step solve at most (WorldSettings::rest_sweeps): a rigid cluster's stop is
  // one.
  int rest_sweeps = 64;
  // WorldSettings::converging_contacts, where mid-step rest runs: an approach is resolved below
  // impact_speed (contact_plan.h), not below resolved_gap_fraction of the gap per max_step, and
  // a deep contact of a rested pair gets no hop (the mid-step lift raises it).
  bool converging_contacts = false;
};

struct ResolutionCounts {
  std::uint64_t collisions = 0;  // plain collision impulses
  std::uint64_t contacts = 0;    // micro-collision impulses
  std::uint64_t passes = 0;
  bool passes_exhausted = false;     // the bound was hit with a contact still approaching
  std::uint64_t rigid_clusters = 0;  // clusters then resolved as rigid bodies
  bool still_approaching = false;    // a contact approached even after that
};

// Applies impulses to `bodies` (indexed as in the manifolds) for every approaching contact of
// `manifolds`, and appends one event per impulse to `events` (when not null) stamped `time`.
ResolutionCounts resolve_contacts(std::span<RigidBody> bodies,
                                  std::span<const ContactManifold> manifolds,
                                  const ResolutionSettings& settings, double time,
                                  std::vector<ContactEvent>* events);

// The same, keeping its working memory from one call to the next (a World resolves every step;
// fresh buffers of hundreds of kilobytes each time cost page faults).
class ContactResolver {
 public:
  ContactResolver();
  // A copy starts with no working memory of its own (it is only a cache).
  ContactResolver(const ContactResolver&);
  ContactResolver& operator=(const ContactResolver&);
  ContactResolver(ContactResolver&&) noexcept;
  ContactResolver& operator=(ContactResolver&&) noexcept;
  ~ContactResolver();

  ResolutionCounts resolve(std::span<RigidBody> bodies, std::span<const ContactManifold> manifolds,
                           const ResolutionSettings& settings, double time,
                           std::vector<ContactEvent>* events);

 private:
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace rugosim
