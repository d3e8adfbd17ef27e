// How one contact is to be resolved (paper §4.2–4.3), from the current velocities: real
// approach and slip, the approach speed the impulse is computed for (perturbed for a
// micro-collision), restitution and friction. Rules in contact_resolution.h.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "engine/collision/contact.h"
#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/event_record.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct ResolutionSettings;

struct ContactPlan {
  ContactBodyState a;  // B's velocity already shifted for a micro-collision (see plan_contact)
  ContactBodyState b;
  double vn = 0.0;         // m/s, real approach speed
  double vt = 0.0;         // m/s, real slip along perp(n)
  double vn_target = 0.0;  // m/s, the approach speed the impulse is computed for
  double restitution = 0.0;
  double mu = 0.0;
  bool micro = false;  // a resting-contact micro-collision
  // Approaching fast enough to need an impulse (contact_resolution.h, "Resolved").
  bool approaching = false;
};

// The motion of a body at a contact point.
ContactBodyState contact_state(const RigidBody& body, const Vec2& point);

// What a plan takes from a contact that its bodies' velocities do not change: resolution plans
// the same contacts over and over as impulses change the velocities, and these need working out
// once per state (positions do not move while impulses are applied).
struct ContactStatics {
  double restitution = 0.0;      // ε of the pair (the larger)
  double restitution_max = 0.0;  // ε_max of the pair (the larger)
  double mu = 0.0;
  double band = 0.0;            // m, λ_a + λ_b (at least the bodies' minimum bands)
  double delta = 0.0;           // m, penetration into the band
  double pressing = 0.0;        // m/s², g_n
  double resolved_speed = 0.0;  // m/s, approach below which the contact is resolved
  // m/s: an approach slower than this stops without restitution and without the
  // micro-collision's hop (0: none does). Set for the contacts of a pair that rested softly
  // (soft_rest.h), whose springs undo the depth a hop would: √(2·|g|·λ).
  double inelastic_below = 0.0;
};
// The speed of a fall through the band, √(2·g_n·λ): the paper's bound between collisions and
// micro-collisions (§4.3). With WorldSettings::converging_contacts, slower approaches rest and
// faster ones are impacts, whatever the step.
inline double impact_speed(const ContactStatics& k) {
  return std::sqrt(2.0 * k.pressing * k.band);
}
ContactStatics contact_statics(const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                               const ResolutionSettings& settings);

// The plan for contact c from its statics and the bodies' motion at it: the same plan, bit for
// bit, as the overload below.
ContactPlan plan_contact(const ContactBodyState& state_a, const ContactBodyState& state_b,
                         const ContactStatics& statics, const Contact& c);

// The plan for contact c between A and B moving as `state_a` and `state_b` (normally
// contact_state of each body; a rigid cluster passes its composite motion instead). Materials,
// friction and whether each side can move come from the bodies.
ContactPlan plan_contact(const ContactBodyState& state_a, const ContactBodyState& state_b,
                         const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                         const ResolutionSettings& settings);

inline ContactPlan plan_contact(const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                                const ResolutionSettings& settings) {
  return plan_contact(contact_state(body_a, c.point), contact_state(body_b, c.point), body_a,
                      body_b, c, settings);
}

// A contact waiting for its impulse in a pass of resolution: `index` into the caller's list.
struct PendingContact {
  double approach = 0.0;  // m/s, the (perturbed) approach speed, negative
  std::size_t index = 0;
};

// Most negative approach first (contact_resolution.h); ties broken by index, so the order never
// depends on the sort's implementation.
void sort_most_approaching_first(std::vector<PendingContact>& pending);

// The events.csv row of an impulse planned by p with result r.
ContactEvent make_event(const RigidBody& a, const RigidBody& b, const ContactManifold& m,
                        const Contact& c, const ContactPlan& p, const ImpulseResult& r,
                        double time);

}  // namespace rugosim
