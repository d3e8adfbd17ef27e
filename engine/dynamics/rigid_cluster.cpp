#include "engine/dynamics/rigid_cluster.h"

#include <algorithm>
#include <cstddef>

#include "engine/core/disjoint_sets.h"
#include "engine/dynamics/collision_impulse.h"
#include "engine/dynamics/contact_plan.h"
#include "engine/dynamics/contact_resolution.h"
#include "engine/dynamics/contact_rows.h"
#include "engine/dynamics/mid_step_rest.h"
#include "engine/dynamics/slow_contacts.h"

namespace rugosim {
namespace {

// Rounds of passes and stops at most (one or two in practice: rigid_cluster_test.cpp).
constexpr int kStopRounds = 4;

// A cluster moving as one rigid body.
struct Composite {
  double mass = 0.0;              // kg
  double inertia = 0.0;           // kg·m², about centre
  Vec2 centre = Vec2::Zero();     // m, centre of mass
  Vec2 velocity = Vec2::Zero();   // m/s
  double angular_velocity = 0.0;  // rad/s

  ContactBodyState at(const Vec2& point) const {
    return {1.0 / mass, 1.0 / inertia, velocity, angular_velocity, point - centre};
  }
};

// The rigid motion with the members' total linear and angular momentum.
Composite make_composite(std::span<const RigidBody> bodies, std::span<const std::size_t> members) {
  Composite c;
  Vec2 momentum = Vec2::Zero();
  for (const std::size_t i : members) {
    const RigidBody& b = bodies[i];
    c.mass += b.mass();
    c.centre += b.mass() * b.state().position;
    momentum += b.mass() * b.state().velocity;
  }
  c.centre /= c.mass;
  c.velocity = momentum / c.mass;
  double angular_momentum = 0.0;  // about the centre
  for (const std::size_t i : members) {
    const RigidBody& b = bodies[i];
    const Vec2 r = b.state().position - c.centre;
    c.inertia += b.inertia() + b.mass() * r.squaredNorm();
    angular_momentum +=
        b.inertia() * b.state().angular_velocity + b.mass() * cross(r, b.state().velocity);
  }
  c.angular_velocity = angular_momentum / c.inertia;
  return c;
}

struct FixedContact {
  std::size_t manifold = 0;
  std::size_t contact = 0;
  bool cluster_is_a = true;
};

}  // namespace

ClusterCounts resolve_rigid_clusters(std::span<RigidBody> bodies,
                                     std::span<const ContactManifold> manifolds,
                                     const ResolutionSettings& settings, double time,
                                     std::vector<ContactEvent>* events) {
  ClusterCounts counts;
  const std::size_t n = bodies.size();
  DisjointSets clusters;
  clusters.reset(n);
  for (const ContactManifold& m : manifolds) {
    if (m.contacts.empty() || bodies[m.body_a].fixed() || bodies[m.body_b].fixed()) continue;
    clusters.unite(m.body_a, m.body_b);
  }
  std::vector<std::uint8_t> marked(n, 0);
  for (const ContactManifold& m : manifolds) {
    for (const Contact& c : m.contacts) {
      if (!plan_contact(bodies[m.body_a], bodies[m.body_b], c, settings).approaching) continue;
      if (!bodies[m.body_a].fixed()) marked[clusters.root(m.body_a)] = 1;
      if (!bodies[m.body_b].fixed()) marked[clusters.root(m.body_b)] = 1;
    }
  }

  std::vector<std::size_t> members;
  std::vector<FixedContact> fixed_contacts;
  std::vector<PendingContact> order;
  for (std::size_t root = 0; root < n; ++root) {
    if (marked[root] == 0) continue;
    members.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (!bodies[i].fixed() && clusters.root(i) == root) members.push_back(i);
    }
    Composite composite = make_composite(bodies, members);
    ++counts.clusters;

    fixed_contacts.clear();
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
      const ContactManifold& m = manifolds[k];
      const bool a_in = !bodies[m.body_a].fixed() && clusters.root(m.body_a) == root;
      const bool b_in = !bodies[m.body_b].fixed() && clusters.root(m.body_b) == root;
      if (a_in == b_in) continue;  // inside the cluster, or not touching it
      for (std::size_t c = 0; c < m.contacts.size(); ++c)
        fixed_contacts.push_back({k, c, a_in});
    }

    // A contact of the cluster with a fixed body: its plan, and whether mid-step rest stops it
    // (a slow approach no deeper than deep_share of its band, as for any contact under mid-step
    // rest) instead of micro-colliding it. Deeper contacts keep the micro-collision that lifts
    // them back.
    struct FixedPlan {
      ContactPlan plan;
      bool stopped = false;
    };
    const auto plan_fixed = [&](const Composite& cluster, const FixedContact& f) {
      const ContactManifold& m = manifolds[f.manifold];
      const Contact& c = m.contacts[f.contact];
      const RigidBody& a = bodies[m.body_a];
      const RigidBody& b = bodies[m.body_b];
      const ContactStatics k = contact_statics(a, b, c, settings);
      FixedPlan out;
      out.plan = f.cluster_is_a
                     ? plan_contact(cluster.at(c.point), contact_state(b, c.point), k, c)
                     : plan_contact(contact_state(a, c.point), cluster.at(c.point), k, c);
      out.stopped = settings.rest_step > 0.0 && out.plan.micro &&
                    k.delta <= deep_share(settings.rest_depth) * k.band;
      return out;
    };
    // What the passes see: a contact that mid-step rest stops is left to the stop below.
    const auto plan = [&](const FixedContact& f) {
      FixedPlan fp = plan_fixed(composite, f);
      if (fp.stopped) fp.plan.approaching = false;
      return fp.plan;
    };
    // Under mid-step rest: the cluster's slow approaches to fixed bodies, all stopped together
    // and inelastically (slow_contacts.h, allowance 0). A micro-collision's hop, √(2·g_n·δ) back
    // out of the band, would lift the whole cluster, a settling pile, as one body (the 50-body
    // pile hopped at 0.22 m/s and slept a second later); one-by-one inelastic stops would leave
    // it rocking about its last contact. Every such contact enters the solve, approaching or not,
    // so that an impulse at one cannot leave another approaching. Returns the contacts pushed.
    const auto stop_slow_contacts = [&]() {
      std::vector<SolverBody> solver(1);
      solver[0] = {1.0 / composite.mass, 1.0 / composite.inertia, composite.centre,
                   composite.velocity, composite.angular_velocity};
      std::vector<SlowContact> slow;
      for (const FixedContact& f : fixed_contacts) {
        const FixedPlan fp = plan_fixed(composite, f);
        if (!fp.stopped) continue;
        const ContactManifold& m = manifolds[f.manifold];
        const Contact& c = m.contacts[f.contact];
        const RigidBody& held = bodies[f.cluster_is_a ? m.body_b : m.body_a];
        solver.push_back({0.0, 0.0, held.state().position, held.state().velocity,
                          held.state().angular_velocity});
        const std::size_t other = solver.size() - 1;
        SlowContact s;
        s.body_a = f.cluster_is_a ? 0 : other;
        s.body_b = f.cluster_is_a ? other : 0;
        s.point = c.point;
        s.normal = c.normal;
        s.friction = fp.plan.mu;
        slow.push_back(s);
      }
      if (slow.empty()) return std::size_t{0};
      const SlowContactResult r = solve_slow_contacts(
          solver, slow,
          rest_sweep_settings(settings.gravity, settings.max_step, settings.rest_sweeps));
      composite.velocity += r.change[0].velocity;
      composite.angular_velocity += r.change[0].angular_velocity;
      return r.pushed;
    };
    // Under mid-step rest the passes and the stop take turns (an impulse of either can make a
    // contact of the other approach) until the stop has nothing left to push, a few rounds at most.
    for (int round = 0; round < kStopRounds; ++round) {
      for (int pass = 0; pass < settings.max_passes; ++pass) {
        order.clear();
        for (std::size_t i = 0; i < fixed_contacts.size(); ++i) {
          const ContactPlan p = plan(fixed_contacts[i]);
          if (p.approaching) order.push_back({p.vn_target, i});
        }
        if (order.empty()) break;
        ++counts.passes;
        sort_most_approaching_first(order);
        for (const PendingContact& candidate : order) {
          const FixedContact& f = fixed_contacts[candidate.index];
          const ContactManifold& m = manifolds[f.manifold];
          const Contact& c = m.contacts[f.contact];
          const ContactPlan p = plan(f);
          if (!p.approaching) continue;
          const ImpulseResult r = collision_impulse(p.a, p.b, c.normal, p.restitution, p.mu);
          if (!r.collision) continue;
          // The impulse on the cluster: +J when it is A, −J when it is B.
          const Vec2 impulse = f.cluster_is_a ? r.impulse : Vec2(-r.impulse);
          const Vec2 arm = c.point - composite.centre;
          composite.velocity += impulse / composite.mass;
          composite.angular_velocity += cross(arm, impulse) / composite.inertia;
          if (p.micro) {
            ++counts.contacts;
          } else {
            ++counts.collisions;
          }
          if (events != nullptr) {
            events->push_back(make_event(bodies[m.body_a], bodies[m.body_b], m, c, p, r, time));
          }
        }
      }
      if (settings.rest_step <= 0.0) break;
      const std::size_t pushed = stop_slow_contacts();
      counts.contacts += pushed;
      if (pushed == 0) break;
    }

    for (const FixedContact& f : fixed_contacts) {
      if (plan_fixed(composite, f).plan.approaching) {
        counts.still_approaching = true;
        break;
      }
    }
    for (const std::size_t i : members) {
      BodyState s = bodies[i].state();
      s.velocity =
          composite.velocity + composite.angular_velocity * perp(s.position - composite.centre);
      s.angular_velocity = composite.angular_velocity;
      bodies[i].set_state(s);
    }
  }
  return counts;
}

}  // namespace rugosim
