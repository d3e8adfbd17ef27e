// The fallback of contact resolution when its passes run out (contact_resolution.h).
//
// Sequential impulses converge slowly in stacks: each impulse between two bodies can make the
// next contact down approach again, and a pile of tens of bodies still has contacts
// approaching after tens of passes. Then every cluster of movable bodies linked by contacts
// that holds an approaching contact is made to move as one rigid body for this state: the
// velocities are replaced by the rigid motion with the same linear and angular momentum (the
// projection in the kinetic-energy metric, so kinetic energy never grows), which leaves no
// contact inside the cluster approaching. The cluster's contacts with fixed bodies are then
// resolved with the cluster as one composite body (mass, centre of mass and inertia of its
// members) by the usual rules and bounded passes, and every member takes the composite motion.
// Physically the cluster behaves, for an instant, as if its contacts had stuck perfectly
// inelastically, which is what a settling pile does anyway.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/collision/contact.h"
#include "engine/dynamics/event_record.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

struct ResolutionSettings;

struct ClusterCounts {
  std::uint64_t clusters = 0;    // clusters made rigid
  std::uint64_t collisions = 0;  // impulses with fixed bodies, by kind
  std::uint64_t contacts = 0;
  std::uint64_t passes = 0;
  // A contact with a fixed body still approaches after the passes. (Contacts inside a cluster
  // are not checked: its members share one rigid motion, so their relative velocity is zero
  // up to rounding.)
  bool still_approaching = false;
};

ClusterCounts resolve_rigid_clusters(std::span<RigidBody> bodies,
                                     std::span<const ContactManifold> manifolds,
                                     const ResolutionSettings& settings, double time,
                                     std::vector<ContactEvent>* events);

}  // namespace rugosim
