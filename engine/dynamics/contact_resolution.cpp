#include "engine/dynamics/contact_resolution.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/rigid_cluster.h"

namespace rugosim {
namespace {

struct ContactRef {
  std::size_t manifold = 0;
  std::size_t contact = 0;
};

// A contact's plan and the versions of its bodies' velocities it was made from (0: none yet).
struct PlanCache {
  ContactPlan plan;
  std::uint64_t version_a = 0;
  std::uint64_t version_b = 0;
  ContactStatics statics;
  ContactBodyState state_a;  // the bodies at the contact, velocities as of the versions
  ContactBodyState state_b;
};

void write_velocity(RigidBody& body, const Vec2& impulse, const Vec2& arm, double sign) {
  if (body.fixed()) return;
  BodyState s = body.state();
  s.velocity += sign * body.inverse_mass() * impulse;
  s.angular_velocity += sign * body.inverse_inertia() * cross(arm, impulse);
  body.set_state(s);
}

}  // namespace

struct ContactResolver::Scratch {
  std::vector<ContactRef> refs;
  std::vector<std::uint64_t> version;
  std::vector<PlanCache> plans;
  std::vector<PendingContact> order;
};

ContactResolver::ContactResolver() = default;
ContactResolver::ContactResolver(const ContactResolver&) {}
ContactResolver& ContactResolver::operator=(const ContactResolver&) {
  return *this;
}
ContactResolver::ContactResolver(ContactResolver&&) noexcept = default;
ContactResolver& ContactResolver::operator=(ContactResolver&&) noexcept = default;
ContactResolver::~ContactResolver() = default;

ResolutionCounts resolve_contacts(std::span<RigidBody> bodies,
                                  std::span<const ContactManifold> manifolds,
                                  const ResolutionSettings& settings, double time,
                                  std::vector<ContactEvent>* events) {
  ContactResolver resolver;
  return resolver.resolve(bodies, manifolds, settings, time, events);
}

ResolutionCounts ContactResolver::resolve(std::span<RigidBody> bodies,
                                          std::span<const ContactManifold> manifolds,
                                          const ResolutionSettings& settings, double time,
                                          std::vector<ContactEvent>* events) {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();
  ResolutionCounts counts;
  std::vector<ContactRef>& refs = scratch_->refs;
  refs.clear();
  for (std::size_t m = 0; m < manifolds.size(); ++m) {
    for (std::size_t k = 0; k < manifolds[m].contacts.size(); ++k)
      refs.push_back({m, k});
  }
  if (refs.empty()) return counts;

  // A plan depends on the contact and on its two bodies' velocities only, and most impulses of a
  // pass leave most bodies alone: each body's velocities carry a version, and a contact is
  // planned again only when a version of its bodies moved on since (the same plan, bit for bit,
  // as planning it afresh).
  std::vector<std::uint64_t>& version = scratch_->version;
  version.assign(bodies.size(), 1);
  std::vector<PlanCache>& plans = scratch_->plans;
  if (plans.size() < refs.size()) plans.resize(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    plans[i].version_a = plans[i].version_b = 0;  // nothing planned yet
    const ContactManifold& m = manifolds[refs[i].manifold];
    const Contact& c = m.contacts[refs[i].contact];
    plans[i].statics = contact_statics(bodies[m.body_a], bodies[m.body_b], c, settings);
    const RestedPair* rested = find_rested(settings.rested, m.body_a, m.body_b);
    ContactStatics& k = plans[i].statics;
    // Deep contacts get the paper's hop; with converging_contacts there are none (the mid-step
    // lift raises them) and every contact of a rested pair is left its allowance.
    const bool deep =
        !settings.converging_contacts && k.delta > deep_share(settings.rest_depth) * k.band;
    if (rested != nullptr && !deep) {
      k.resolved_speed =
          std::max(k.resolved_speed, k.pressing * settings.rest_step + rested->allowance);
    }
    if (rested != nullptr && rested->soft)
      k.inelastic_below = std::sqrt(2.0 * settings.gravity.norm() * k.band);
    plans[i].state_a = contact_state(bodies[m.body_a], c.point);
    plans[i].state_b = contact_state(bodies[m.body_b], c.point);
  }
  const auto plan = [&](std::size_t i) -> const ContactPlan& {
    const ContactManifold& m = manifolds[refs[i].manifold];
    PlanCache& cache = plans[i];
    if (cache.version_a != version[m.body_a] || cache.version_b != version[m.body_b]) {
      // Only the velocities change; arms and masses were taken once.
      const BodyState& sa = bodies[m.body_a].state();
      const BodyState& sb = bodies[m.body_b].state();
      cache.state_a.velocity = sa.velocity;
      cache.state_a.angular_velocity = sa.angular_velocity;
      cache.state_b.velocity = sb.velocity;
      cache.state_b.angular_velocity = sb.angular_velocity;
      cache.plan =
          plan_contact(cache.state_a, cache.state_b, cache.statics, m.contacts[refs[i].contact]);
      cache.version_a = version[m.body_a];
      cache.version_b = version[m.body_b];
    }
    return cache.plan;
  };

  std::vector<PendingContact>& order = scratch_->order;
  for (int pass = 0; pass < settings.max_passes; ++pass) {
    order.clear();
    for (std::size_t i = 0; i < refs.size(); ++i) {
      const ContactPlan& p = plan(i);
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
      const ContactPlan& p = plan(candidate.index);
      if (!p.approaching) continue;
      const ImpulseResult r = collision_impulse(p.a, p.b, c.normal, p.restitution, p.mu);
      if (!r.collision) continue;  // degenerate: nothing can change v_n here
      write_velocity(a, r.impulse, p.a.arm, 1.0);
      write_velocity(b, r.impulse, p.b.arm, -1.0);
      if (!a.fixed()) ++version[m.body_a];
      if (!b.fixed()) ++version[m.body_b];
      ++applied;
      if (p.micro) {
        ++counts.contacts;
      } else {
        ++counts.collisions;
      }
      // p is still this contact's plan from before the impulse: only plan() replaces it.
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
