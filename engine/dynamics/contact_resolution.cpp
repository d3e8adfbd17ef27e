#include "engine/dynamics/contact_resolution.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/dynamics/collision_impulse.h"
#include "engine/geometry/friction.h"

namespace rugosim {
namespace {

struct ContactRef {
  std::size_t manifold = 0;
  std::size_t contact = 0;
};

// Everything needed to apply one contact's impulse, from the bodies' current velocities.
struct ContactPlan {
  ContactBodyState a;
  ContactBodyState b;
  double vn = 0.0;         // m/s, real approach speed
  double vt = 0.0;         // m/s, real slip along perp(n)
  double vn_target = 0.0;  // m/s, the approach speed the impulse is computed for
  double restitution = 0.0;
  double mu = 0.0;
  bool micro = false;  // a resting-contact micro-collision
};

ContactBodyState contact_state(const RigidBody& body, const Vec2& point) {
  ContactBodyState s;
  s.inverse_mass = body.inverse_mass();
  s.inverse_inertia = body.inverse_inertia();
  s.velocity = body.state().velocity;
  s.angular_velocity = body.state().angular_velocity;
  s.arm = point - body.state().position;
  return s;
}

// g_n of the header: how hard gravity presses A and B together along n, m/s².
double pressing_gravity(const RigidBody& a, const RigidBody& b, const Vec2& gravity,
                        const Vec2& n) {
  const double along = gravity.dot(n);
  double pressing = 0.0;
  if (!a.fixed()) pressing = std::max(pressing, -along);
  if (!b.fixed()) pressing = std::max(pressing, along);
  return pressing;
}

ContactPlan plan_contact(const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                         const ResolutionSettings& settings) {
  ContactPlan p;
  p.a = contact_state(body_a, c.point);
  p.b = contact_state(body_b, c.point);
  const Vec2 u = relative_contact_velocity(p.a, p.b);
  p.vn = u.dot(c.normal);
  p.vt = u.dot(perp(c.normal));
  p.vn_target = p.vn;
  const Material& ma = body_a.material();
  const Material& mb = body_b.material();
  const double eps = std::max(ma.restitution, mb.restitution);
  const double eps_max = std::max(ma.restitution_max, mb.restitution_max);
  p.restitution = eps;
  p.mu = contact_friction(body_a.friction_coefficient(c.segment_a, c.t_a, settings.friction_gain),
                          body_b.friction_coefficient(c.segment_b, c.t_b, settings.friction_gain));

  const double band =
      std::max(c.lambda_a + c.lambda_b, body_a.shape().min_band() + body_b.shape().min_band());
  const double delta = std::clamp(band - c.distance, 0.0, band);
  const double g_n = pressing_gravity(body_a, body_b, settings.gravity, c.normal);
  if (g_n > 0.0 && delta > 0.0 && p.vn < 0.0 && p.vn > -std::sqrt(2.0 * g_n * band)) {
    p.micro = true;
    p.vn_target = std::min(p.vn, -std::sqrt(2.0 * g_n * delta));
    const double ratio = delta / band;
    p.restitution = std::clamp((eps_max - eps) * ratio * ratio + eps, 0.0, 1.0);
    // Only u = u_A − u_B enters the impulse, so shifting B's velocity along n by
    // (v_n − v_n*) makes the impulse see the perturbed approach speed.
    p.b.velocity += (p.vn - p.vn_target) * c.normal;
  }
  return p;
}

void write_velocity(RigidBody& body, const Vec2& impulse, const Vec2& arm, double sign) {
  if (body.fixed()) return;
  BodyState s = body.state();
  s.velocity += sign * body.inverse_mass() * impulse;
  s.angular_velocity += sign * body.inverse_inertia() * cross(arm, impulse);
  body.set_state(s);
}

ContactEvent make_event(const RigidBody& a, const RigidBody& b, const ContactManifold& m,
                        const Contact& c, const ContactPlan& p, const ImpulseResult& r,
                        double time) {
  // Contact parameters lie in [0, 1]; the end of a segment is the start of the next.
  auto input_param = [](const RigidBody& body, std::size_t segment, double t) {
    if (t >= 1.0) return body.to_input_param({(segment + 1) % body.curve().size(), 0.0});
    return body.to_input_param({segment, t});
  };
  const CurveParam pa = input_param(a, c.segment_a, c.t_a);
  const CurveParam pb = input_param(b, c.segment_b, c.t_b);
  ContactEvent e;
  e.time = time;
  e.kind = p.micro ? EventKind::kContact : EventKind::kCollision;
  e.body_a = m.body_a;
  e.body_b = m.body_b;
  e.segment_a = pa.segment;
  e.segment_b = pb.segment;
  e.t_a = pa.t;
  e.t_b = pb.t;
  e.point = c.point;
  e.normal = c.normal;
  e.lambda_a = c.lambda_a;
  e.lambda_b = c.lambda_b;
  e.mu = p.mu;
  e.vn = p.vn;
  e.vt = p.vt;
  e.jn = r.jn;
  e.jt = r.jt;
  return e;
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

  struct Candidate {
    double approach = 0.0;  // m/s, the (perturbed) approach speed, negative
    std::size_t ref = 0;
  };
  std::vector<Candidate> order;
  for (int pass = 0; pass < settings.max_passes; ++pass) {
    order.clear();
    for (std::size_t i = 0; i < refs.size(); ++i) {
      const ContactManifold& m = manifolds[refs[i].manifold];
      const ContactPlan p =
          plan_contact(bodies[m.body_a], bodies[m.body_b], m.contacts[refs[i].contact], settings);
      if (p.vn < 0.0) order.push_back({p.vn_target, i});
    }
    if (order.empty()) return counts;
    ++counts.passes;
    // Ties broken by position, so the order never depends on the sort's implementation.
    std::sort(order.begin(), order.end(), [](const Candidate& x, const Candidate& y) {
      return x.approach < y.approach || (x.approach == y.approach && x.ref < y.ref);
    });
    std::size_t applied = 0;
    for (const Candidate& candidate : order) {
      const ContactRef& ref = refs[candidate.ref];
      const ContactManifold& m = manifolds[ref.manifold];
      const Contact& c = m.contacts[ref.contact];
      RigidBody& a = bodies[m.body_a];
      RigidBody& b = bodies[m.body_b];
      // Earlier impulses of this pass may have changed these velocities.
      const ContactPlan p = plan_contact(a, b, c, settings);
      if (!(p.vn < 0.0)) continue;
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
  // Out of passes: is anything still approaching?
  for (const ContactRef& ref : refs) {
    const ContactManifold& m = manifolds[ref.manifold];
    const ContactPlan p =
        plan_contact(bodies[m.body_a], bodies[m.body_b], m.contacts[ref.contact], settings);
    if (p.vn < 0.0) {
      counts.passes_exhausted = true;
      break;
    }
  }
  return counts;
}

}  // namespace rugosim
