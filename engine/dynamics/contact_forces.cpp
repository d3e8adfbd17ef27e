#include "engine/dynamics/contact_forces.h"

#include <algorithm>
#include <cmath>

#include "engine/dynamics/collision_impulse.h"

namespace rugosim {
namespace {

// A contact row with everything that stays fixed during the sweeps.
struct Row {
  Vec2 arm_a = Vec2::Zero();
  Vec2 arm_b = Vec2::Zero();
  Vec2 tangent = Vec2::Zero();
  double normal_mass = 0.0;     // 1/K_nn: φ_n per m/s of normal velocity
  double tangent_mass = 0.0;    // 1/K_tt
  double normal_target = 0.0;   // m/s: the least (Kφ)_n that keeps the end gap ≥ 0
  double tangent_target = 0.0;  // m/s: the (Kφ)_t that stops the slip at the step's end
  Vec2 impulse = Vec2::Zero();  // φ = (φ_n, φ_t), N·s
};

// The velocity changes the accumulated φ has made so far, per body.
struct Change {
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;
};

Vec2 point_change(const Change& c, const Vec2& arm) {
  return c.velocity + c.angular_velocity * perp(arm);
}

}  // namespace

ForceResult solve_contact_forces(std::span<const ForceBody> bodies,
                                 std::span<ForceContact> contacts, const Vec2& gravity, double h,
                                 const ForceSettings& settings) {
  ForceResult result;
  result.acceleration.assign(bodies.size(), Vec2::Zero());
  result.angular_acceleration.assign(bodies.size(), 0.0);
  const auto movable = [&](std::size_t i) { return bodies[i].inverse_mass > 0.0; };

  std::vector<Change> change(bodies.size());
  const auto apply = [&](const ForceContact& c, const Row& r, const Vec2& delta) {
    const ForceBody& a = bodies[c.body_a];
    const ForceBody& b = bodies[c.body_b];
    change[c.body_a].velocity += a.inverse_mass * delta;
    change[c.body_a].angular_velocity += a.inverse_inertia * cross(r.arm_a, delta);
    change[c.body_b].velocity -= b.inverse_mass * delta;
    change[c.body_b].angular_velocity -= b.inverse_inertia * cross(r.arm_b, delta);
  };

  // m/s: the change the accumulated φ has made so far to contact c's relative velocity.
  const auto relative_change = [&](const ForceContact& c, const Row& r) -> Vec2 {
    return point_change(change[c.body_a], r.arm_a) - point_change(change[c.body_b], r.arm_b);
  };

  std::vector<Row> rows(contacts.size());
  double speed_scale = gravity.norm() * h;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    ForceContact& c = contacts[i];
    Row& r = rows[i];
    const ForceBody& a = bodies[c.body_a];
    const ForceBody& b = bodies[c.body_b];
    ContactBodyState sa{a.inverse_mass, a.inverse_inertia, a.velocity, a.angular_velocity,
                        c.point - a.position};
    ContactBodyState sb{b.inverse_mass, b.inverse_inertia, b.velocity, b.angular_velocity,
                        c.point - b.position};
    r.arm_a = sa.arm;
    r.arm_b = sb.arm;
    r.tangent = perp(c.normal);
    const Mat2 k = collision_matrix(sa, sb);
    const double k_nn = c.normal.dot(k * c.normal);
    const double k_tt = r.tangent.dot(k * r.tangent);
    if (!(k_nn > 0.0)) {
      c.force = Vec2::Zero();
      continue;  // no force moves this contact: a row of zeros
    }
    r.normal_mass = 1.0 / k_nn;
    r.tangent_mass = k_tt > 0.0 ? 1.0 / k_tt : 0.0;
    const Vec2 w = relative_contact_velocity(sa, sb);
    const Vec2 a_g =
        (movable(c.body_a) ? gravity : Vec2::Zero()) - (movable(c.body_b) ? gravity : Vec2::Zero());
    // s + h·w_n + ½h²·a_g,n + ½h·(Kφ)_n ≥ 0  ⇔  (Kφ)_n ≥ −2(s/h + w_n) − h·a_g,n.
    r.normal_target = -2.0 * (c.gap / h + w.dot(c.normal)) - h * a_g.dot(c.normal);
    r.tangent_target = -(w.dot(r.tangent) + h * a_g.dot(r.tangent));
    speed_scale = std::max(speed_scale, r.normal_target);
    // Warm start: last step's force over this step, inside this step's cone.
    const double phi_n = std::max(0.0, c.force.x() * h);
    const double limit = c.friction * phi_n;
    r.impulse = Vec2(phi_n, std::clamp(c.force.y() * h, -limit, limit));
    apply(c, r, r.impulse.x() * c.normal + r.impulse.y() * r.tangent);
  }

  const double tolerance = settings.tolerance * speed_scale;
  for (int sweep = 0; sweep < settings.max_sweeps; ++sweep) {
    double largest = 0.0;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const ForceContact& c = contacts[i];
      Row& r = rows[i];
      if (r.normal_mass == 0.0) continue;
      // Friction first, against the cone of the normal impulse so far (Box2D 2.4.1's order).
      if (r.tangent_mass > 0.0) {
        const double dw_t = relative_change(c, r).dot(r.tangent);
        const double limit = c.friction * r.impulse.x();
        const double phi_t =
            std::clamp(r.impulse.y() + r.tangent_mass * (r.tangent_target - dw_t), -limit, limit);
        const double delta = phi_t - r.impulse.y();
        if (delta != 0.0) {
          r.impulse.y() = phi_t;
          apply(c, r, delta * r.tangent);
          largest = std::max(largest, std::abs(delta) / r.tangent_mass);
        }
      }
      const double dw_n = relative_change(c, r).dot(c.normal);
      const double phi_n = std::max(0.0, r.impulse.x() + r.normal_mass * (r.normal_target - dw_n));
      const double delta = phi_n - r.impulse.x();
      if (delta != 0.0) {
        r.impulse.x() = phi_n;
        apply(c, r, delta * c.normal);
        largest = std::max(largest, std::abs(delta) / r.normal_mass);
      }
    }
    result.sweeps = sweep + 1;
    result.residual = largest;
    if (largest <= tolerance) {
      result.converged = true;
      break;
    }
  }

  for (std::size_t i = 0; i < contacts.size(); ++i)
    contacts[i].force = rows[i].impulse / h;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!movable(i)) continue;
    result.acceleration[i] = gravity + change[i].velocity / h;
    result.angular_acceleration[i] = change[i].angular_velocity / h;
  }
  return result;
}

}  // namespace rugosim
