#include "engine/dynamics/contact_plan.h"

#include <algorithm>
#include <cmath>

#include "engine/dynamics/contact_resolution.h"
#include "engine/geometry/friction.h"

namespace rugosim {
namespace {

// g_n of contact_resolution.h: how hard gravity presses A and B together along n, m/s².
double pressing_gravity(const RigidBody& a, const RigidBody& b, const Vec2& gravity,
                        const Vec2& n) {
  const double along = gravity.dot(n);
  double pressing = 0.0;
  if (!a.fixed()) pressing = std::max(pressing, -along);
  if (!b.fixed()) pressing = std::max(pressing, along);
  return pressing;
}

}  // namespace

ContactBodyState contact_state(const RigidBody& body, const Vec2& point) {
  ContactBodyState s;
  s.inverse_mass = body.inverse_mass();
  s.inverse_inertia = body.inverse_inertia();
  s.velocity = body.state().velocity;
  s.angular_velocity = body.state().angular_velocity;
  s.arm = point - body.state().position;
  return s;
}

ContactStatics contact_statics(const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                               const ResolutionSettings& settings) {
  ContactStatics k;
  const Material& ma = body_a.material();
  const Material& mb = body_b.material();
  k.restitution = std::max(ma.restitution, mb.restitution);
  k.restitution_max = std::max(ma.restitution_max, mb.restitution_max);
  k.mu = contact_friction(body_a.friction_coefficient(c.segment_a, c.t_a, settings.friction_gain),
                          body_b.friction_coefficient(c.segment_b, c.t_b, settings.friction_gain));
  k.band = std::max(c.lambda_a + c.lambda_b, body_a.shape().min_band() + body_b.shape().min_band());
  k.delta = std::clamp(k.band - c.distance, 0.0, k.band);
  k.pressing = pressing_gravity(body_a, body_b, settings.gravity, c.normal);
  // A share of the gap per max_step decides, at a given step, what a step-independent rule
  // (converging_contacts) decides by speed alone.
  k.resolved_speed = settings.converging_contacts
                         ? impact_speed(k)
                         : settings.resolved_gap_fraction * c.distance / settings.max_step;
  // (With converging_contacts only a rested pair's contacts get that: contact_resolution.cpp.)
  if (!settings.converging_contacts && settings.rest_step > 0.0 &&
      k.delta <= deep_share(settings.rest_depth) * k.band) {
    k.resolved_speed = std::max(k.resolved_speed, k.pressing * settings.rest_step);
  }
  return k;
}

ContactPlan plan_contact(const ContactBodyState& state_a, const ContactBodyState& state_b,
                         const ContactStatics& k, const Contact& c) {
  ContactPlan p;
  p.a = state_a;
  p.b = state_b;
  const Vec2 u = relative_contact_velocity(p.a, p.b);
  p.vn = u.dot(c.normal);
  p.vt = u.dot(perp(c.normal));
  p.vn_target = p.vn;
  p.restitution = k.restitution;
  p.mu = k.mu;
  p.approaching = p.vn < -k.resolved_speed;
  const double g_n = k.pressing;
  if (p.vn < 0.0 && p.vn > -k.inelastic_below) {
    p.restitution = 0.0;
  } else if (g_n > 0.0 && k.delta > 0.0 && p.vn < 0.0 && p.vn > -impact_speed(k)) {
    p.micro = true;
    p.vn_target = std::min(p.vn, -std::sqrt(2.0 * g_n * k.delta));
    const double ratio = k.delta / k.band;
    p.restitution =
        std::clamp((k.restitution_max - k.restitution) * ratio * ratio + k.restitution, 0.0, 1.0);
    // Only u = u_A − u_B enters the impulse, so shifting B's velocity along n by
    // (v_n − v_n*) makes the impulse see the perturbed approach speed.
    p.b.velocity += (p.vn - p.vn_target) * c.normal;
  }
  return p;
}

ContactPlan plan_contact(const ContactBodyState& state_a, const ContactBodyState& state_b,
                         const RigidBody& body_a, const RigidBody& body_b, const Contact& c,
                         const ResolutionSettings& settings) {
  return plan_contact(state_a, state_b, contact_statics(body_a, body_b, c, settings), c);
}

void sort_most_approaching_first(std::vector<PendingContact>& pending) {
  std::sort(pending.begin(), pending.end(), [](const PendingContact& x, const PendingContact& y) {
    return x.approach < y.approach || (x.approach == y.approach && x.index < y.index);
  });
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

}  // namespace rugosim
