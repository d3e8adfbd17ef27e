#include "engine/dynamics/contact_resolution.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/rigid_cluster.h"

namespace rugosim {
namespace {

struct ContactRef {
  std::size_t manifold = 0;
  std::size_t contact = 0;
};

void write_velocity(RigidBody& body, const Vec2& impulse, const Vec2& arm, double sign) {
  if (body.fixed()) return;
  BodyState s = body.state();
  s.velocity += sign * body.inverse_mass() * impulse;
  s.angular_velocity += sign * body.inverse_inertia() * cross(arm, impulse);
  body.set_state(s);
}

}  // namespace

ResolutionCounts resolve_contacts(std::span<RigidBody> bodies,
                                  std::span<const ContactManifold> manifolds,
                                  const ResolutionSettings& settings, double time,
                                  std::vector<ContactEvent>* events) {
  ResolutionCounts counts;
  std::vector<ContactRef> refs;
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    for (std::size_t k = 0; k < manifolds[m].contacts.size(); ++k)
      refs.push_back({m, k});
  }
  if (refs.empty()) return counts;

  std::vector<PendingContact> order;
  for (int pass = 0; pass < settings.max_passes; ++pass) {
    order.clear();
    for (std::size_t i = 0; i < refs.size(); ++i) {
      const ContactManifold& m = manifolds[refs[i].manifold];
      const ContactPlan p =
          plan_contact(bodies[m.body_a], bodies[m.body_b], m.contacts[refs[i].contact], settings);
      if (p.approaching) order.push_back({p.vn_target, i});
    }
    if (order.empty()) return counts;
    ++counts.passes;
    sort_most_approaching_first(order);
    std::size_t applied = 0;
    for (const PendingContact& candidate : order) {
      const ContactRef& ref = refs[candidate.index];
      const ContactManifold& m = manifolds[ref.manifold];
      const Contact& c = m.contacts[ref.contact];
      RigidBody& a = bodies[m.body_a];
      RigidBody& b = bodies[m.body_b];
      // Earlier impulses of this pass may have changed these velocities.
      const ContactPlan p = plan_contact(a, b, c, settings);
      if (!p.approaching) continue;
      const ImpulseResult r = collision_impulse(p.a, p.b, c.normal, p.restitution, p.mu);
      if (!r.collision) continue;  // degenerate: nothing can change v_n here
      write_velocity(a, r.impulse, p.a.arm, 1.0);
      write_velocity(b, r.impulse, p.b.arm, -1.0);
      ++applied;
      if (p.micro) {
        ++counts.contacts;
      } else {
        ++counts.collisions;
      }
      if (events != nullptr) events->push_back(make_event(a, b, m, c, p, r, time));
    }
    if (applied == 0) return counts;
  }
  // Out of passes: clusters with a contact still approaching move as rigid bodies
  // (rigid_cluster.h).
  const ClusterCounts clusters = resolve_rigid_clusters(bodies, manifolds, settings, time, events);
  counts.rigid_clusters = clusters.clusters;
  counts.collisions += clusters.collisions;
  counts.contacts += clusters.contacts;
  counts.passes += clusters.passes;
  counts.passes_exhausted = true;
  counts.still_approaching = clusters.still_approaching;
  return counts;
}

}  // namespace rugosim
