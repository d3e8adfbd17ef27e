#include "engine/dynamics/contact_rows.h"

#include <algorithm>
#include <cmath>

#include "engine/dynamics/collision_impulse.h"

namespace rugosim {
namespace {

// What stays fixed of a row during the sweeps.
struct RowMasses {
  Vec2 arm_a = Vec2::Zero();
  Vec2 arm_b = Vec2::Zero();
  Vec2 tangent = Vec2::Zero();
  double normal_mass = 0.0;   // 1/K_nn: x_n per m/s of normal velocity
  double tangent_mass = 0.0;  // 1/K_tt
};

Vec2 point_change(const VelocityChange& c, const Vec2& arm) {
  return c.velocity + c.angular_velocity * perp(arm);
}

}  // namespace

StartedRow start_row(std::span<const SolverBody> bodies, std::size_t body_a, std::size_t body_b,
                     const Vec2& point, const Vec2& normal, double friction) {
  StartedRow out;
  out.row.body_a = body_a;
  out.row.body_b = body_b;
  out.row.point = point;
  out.row.normal = normal;
  out.row.friction = friction;
  const SolverBody& a = bodies[body_a];
  const SolverBody& b = bodies[body_b];
  const ContactBodyState sa{a.inverse_mass, a.inverse_inertia, a.velocity, a.angular_velocity,
                            point - a.position};
  const ContactBodyState sb{b.inverse_mass, b.inverse_inertia, b.velocity, b.angular_velocity,
                            point - b.position};
  out.velocity = relative_contact_velocity(sa, sb);
  return out;
}

RowSolution solve_velocity_rows(std::span<const SolverBody> bodies, std::span<VelocityRow> rows,
                                const SweepSettings& settings) {
  RowSolution result;
  result.change.assign(bodies.size(), VelocityChange{});
  std::vector<VelocityChange>& change = result.change;
  const auto apply = [&](const VelocityRow& c, const RowMasses& r, const Vec2& delta) {
    const SolverBody& a = bodies[c.body_a];
    const SolverBody& b = bodies[c.body_b];
    change[c.body_a].velocity += a.inverse_mass * delta;
    change[c.body_a].angular_velocity += a.inverse_inertia * cross(r.arm_a, delta);
    change[c.body_b].velocity -= b.inverse_mass * delta;
    change[c.body_b].angular_velocity -= b.inverse_inertia * cross(r.arm_b, delta);
  };
  // m/s: the change the accumulated impulses have made so far to the row's relative velocity.
  // Typed Vec2: an `auto` Eigen expression would outlive its operands.
  const auto relative_change = [&](const VelocityRow& c, const RowMasses& r) -> Vec2 {
    return point_change(change[c.body_a], r.arm_a) - point_change(change[c.body_b], r.arm_b);
  };

  std::vector<RowMasses> masses(rows.size());
  double speed_scale = settings.speed_floor;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    VelocityRow& c = rows[i];
    RowMasses& r = masses[i];
    const SolverBody& a = bodies[c.body_a];
    const SolverBody& b = bodies[c.body_b];
    const ContactBodyState sa{a.inverse_mass, a.inverse_inertia, Vec2::Zero(), 0.0,
                              c.point - a.position};
    const ContactBodyState sb{b.inverse_mass, b.inverse_inertia, Vec2::Zero(), 0.0,
                              c.point - b.position};
    r.arm_a = sa.arm;
    r.arm_b = sb.arm;
    r.tangent = perp(c.normal);
    const Mat2 k = collision_matrix(sa, sb);
    const double k_nn = c.normal.dot(k * c.normal);
    const double k_tt = r.tangent.dot(k * r.tangent);
    if (!(k_nn > 0.0)) {
      c.impulse = Vec2::Zero();
      continue;  // no impulse moves this contact: a row of zeros
    }
    r.normal_mass = 1.0 / k_nn;
    speed_scale = std::max(speed_scale, c.normal_target);
    r.tangent_mass = k_tt > 0.0 ? 1.0 / k_tt : 0.0;
    const double x_n = std::max(0.0, c.impulse.x());
    const double limit = c.friction * x_n;
    c.impulse = Vec2(x_n, std::clamp(c.impulse.y(), -limit, limit));
    apply(c, r, c.impulse.x() * c.normal + c.impulse.y() * r.tangent);
  }

  const double tolerance = settings.tolerance * speed_scale;
  for (int sweep = 0; sweep < settings.max_sweeps; ++sweep) {
    double largest = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      VelocityRow& c = rows[i];
      const RowMasses& r = masses[i];
      if (r.normal_mass == 0.0) continue;
      // Friction first, against the cone of the normal impulse so far.
      if (r.tangent_mass > 0.0) {
        const double du_t = relative_change(c, r).dot(r.tangent);
        const double limit = c.friction * c.impulse.x();
        const double x_t =
            std::clamp(c.impulse.y() + r.tangent_mass * (c.tangent_target - du_t), -limit, limit);
        const double delta = x_t - c.impulse.y();
        if (delta != 0.0) {
          c.impulse.y() = x_t;
          apply(c, r, delta * r.tangent);
          largest = std::max(largest, std::abs(delta) / r.tangent_mass);
        }
      }
      const double du_n = relative_change(c, r).dot(c.normal);
      const double x_n = std::max(0.0, c.impulse.x() + r.normal_mass * (c.normal_target - du_n));
      const double delta = x_n - c.impulse.x();
      if (delta != 0.0) {
        c.impulse.x() = x_n;
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
  return result;
}

}  // namespace rugosim
